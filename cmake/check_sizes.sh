#!/usr/bin/env bash
# The size limits of docs/architecture.md ("Keeping it readable"): no source file over 500 lines
# (tests included) and no function over 80 lines outside tests. Prints each one that is over, as
# FILE:LINE, and exits 1 when there is one that cmake/size_exceptions.txt does not list, or one it
# lists that grew or is now within the limit (then the line must go). CTest: Tree.SizeLimits.
#   cmake/check_sizes.sh SOURCE_DIR
# Functions are found by the layout clang-format gives them (.clang-format): a definition at
# column 0 (or a member at column 4 inside a class at column 0) whose head ends with `{`, closed by
# a `}` at the same column. Raw strings are skipped.
set -euo pipefail
cd "$1"
max_file=500 max_function=80
files() {  # tracked files still present, or every file when this is not a git checkout (a release)
    if git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
        git ls-files --cached --others --exclude-standard "$@" | while read -r f; do [[ -f "$f" ]] && echo "$f"; done
    else find . -type f \( -false $(printf -- '-o -path ./%s ' "$@") \) | sed 's|^\./||'; fi
}
found=""  # "FILE NAME LINES" per line: what is over the limits now
while read -r lines file; do
    [[ "$file" == total ]] && continue
    (( lines > max_file )) && found+="$file (file) $lines"$'\n'
done < <(files '*.cpp' '*.h' '*.glsl' '*.comp' '*.sh' '*.cmake' '*.js' | grep -v '^build' | xargs -r wc -l)

functions_over() {
    awk -v limit="$max_function" '
    function report(start, end, head) {
        if (end - start + 1 > limit) printf "%s %s %d\n", FILENAME, head, end - start + 1
        found = 1
    }
    FNR == 1 { in_raw = 0; open_col = -1; class_col0 = 0; prev_start = 0 }
    {
        line = $0
        if (in_raw) { if (index(line, ")\"")) in_raw = 0; next }
        if (line ~ /R"[A-Za-z_]*\(/ && !(line ~ /R"[A-Za-z_]*\(.*\)[A-Za-z_]*"/)) in_raw = 1
        match(line, /^ */); col = RLENGTH
        if (open_col >= 0) {  # inside a function: wait for its closing brace
            if (line ~ ("^" sprintf("%" open_col "s", "") "}")) { report(open_start, FNR, open_head); open_col = -1 }
            next
        }
        if (col == 0 && line ~ /^(class|struct) [^;]*\{$/) class_col0 = 1
        if (col == 0 && line ~ /^};/) class_col0 = 0
        # The first line of a statement: the line after one that ends a statement or a block.
        if (stmt_done) { head_start = FNR; head = line; head_col = col }
        else head = head " " line
        stmt_done = (line ~ /[;{}]\s*(\/\/.*)?$/ || line ~ /^\s*$/ || line ~ /^\s*(\/\/|#)/)
        if ((head_col == 0 || (head_col == 4 && class_col0)) && line ~ /\{$/ && head ~ /\(/ &&
            head !~ /^\s*(namespace|class|struct|enum|union|extern)/ && head !~ /^[^(]*=/) {
            sub(/\(.*/, "", head); n = split(head, words, " ")
            open_col = head_col; open_start = head_start; open_head = words[n]
        }
    }
    BEGIN { stmt_done = 1 }' "$@"
}
found+="$(functions_over $(files '*.cpp' '*.h' | grep -v -e '^build' -e '/tests/' -e '_test\.cpp$'))"

# Compare with the known exceptions (the debt being paid: each line goes when its item is fixed).
known="$(grep -v -e '^#' -e '^$' cmake/size_exceptions.txt || true)"
status=0
while read -r file name lines; do
    [[ -z "$file" ]] && continue
    allowed="$(awk -v f="$file" -v n="$name" '$1 == f && $2 == n {print $3}' <<< "$known")"
    what="$([[ $name == "(file)" ]] && echo "the file" || echo "$name")"
    limit="$([[ $name == "(file)" ]] && echo "$max_file" || echo "$max_function")"
    if [[ -z "$allowed" ]]; then
        echo "$file: $what is $lines lines, over $limit: split it (a file by topic, a function into named steps)"
        status=1
    elif (( lines > allowed )); then
        echo "$file: $what grew to $lines lines (cmake/size_exceptions.txt allows it $allowed until it is split)"
        status=1
    fi
done <<< "$found"
while read -r file name lines; do
    [[ -z "$file" ]] && continue
    if ! grep -q "^$file $name " <<< "$found"; then
        echo "$file: $name is within the limits now: delete its line from cmake/size_exceptions.txt"
        status=1
    fi
done <<< "$known"
echo "sizes: $(grep -c . <<< "$known") known exceptions (cmake/size_exceptions.txt), $([[ $status == 0 ]] && echo "nothing new" || echo "see above")"
exit $status
