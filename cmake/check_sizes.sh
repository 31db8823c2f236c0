#!/usr/bin/env bash
# The size guide of docs/architecture.md ("Keeping it readable"): about 500 lines a file (tests
# included) and 80 a function outside tests are signals to split by topic, so the script warns
# about each one over them, as FILE: what, and about the files within 5 % of the guide. A file
# over twice the guide (1000 lines) or a function over twice it (160) fails: that is no longer a
# file of one concept or a list of named steps. CTest: Tree.SizeLimits; .ci/run prints the warnings.
#   cmake/check_sizes.sh SOURCE_DIR
# Functions are found by the layout clang-format gives them (.clang-format): a definition at
# column 0 (or a member at column 4 inside a class at column 0) whose head ends with `{`, closed by
# a `}` at the same column. Raw strings are skipped.
set -euo pipefail
cd "$1"
max_file=500
max_function=80
files() {  # tracked files still present, or every file when this is not a git checkout (a release)
    if git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
        git ls-files --cached --others --exclude-standard "$@" | while read -r f; do [[ -f "$f" ]] && echo "$f"; done
    else find . -type f \( -false $(printf -- '-o -path ./%s ' "$@") \) | sed 's|^\./||'; fi
}
# "LINES FILE" per line for every source file, counted once.
line_counts="$(files '*.cpp' '*.h' '*.glsl' '*.comp' '*.sh' '*.cmake' '*.js' | grep -v '^build' |
    xargs -r wc -l | grep -v ' total$' || true)"
found=""  # "FILE NAME LINES" per line: what is over the limits now
while read -r lines file; do
    [[ -z "$file" ]] && continue
    (( lines > max_file )) && found+="$file (file) $lines"$'\n'
done <<< "$line_counts"

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

status=0
while read -r file name lines; do
    [[ -z "$file" ]] && continue
    what="$([[ $name == "(file)" ]] && echo "the file" || echo "$name")"
    limit="$([[ $name == "(file)" ]] && echo "$max_file" || echo "$max_function")"
    if (( lines > 2 * limit )); then
        echo "error: $file: $what is $lines lines, over twice the guide of $limit: split it by topic"
        status=1
    else
        echo "warning: $file: $what is $lines lines, over the guide of $limit: split it by topic"
    fi
done <<< "$found"
while read -r lines file; do
    [[ -z "$file" ]] && continue
    (( lines * 100 >= max_file * 95 && lines <= max_file )) &&
        echo "note: $file is $lines lines, near the guide of $max_file: split it before it is full"
done <<< "$line_counts"
exit $status
