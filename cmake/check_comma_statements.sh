#!/usr/bin/env bash
# Format.NoCommaStatements: one statement a line. An expression statement chained with the comma
# operator (`m.diffuse = a, m.ambient = b;`, `++i, ++j;`) is two statements squeezed into one;
# write each on its own line. Declarations (`int a = 0, b = 1;`), argument lists, initializer
# lists, enumerators and for-loop headers are not statements and are never reported.
#
# C++ and GLSL, read by a small scanner: comments, string and character literals (raw strings
# too) are skipped; a statement ends at `;`, `{` or `}` outside parentheses and brackets; a
# leading `if (...)`, `for (...)`, `while (...)`, `switch (...)`, `else`, `do` or label is not part
# of it. A statement is reported when it starts with an assignment or an increment and holds a
# comma outside parentheses, brackets and template arguments. (A statement that starts with a call cannot be told
# from the elements of an initializer list this way: chained calls are left to review.) Prints FILE:LINE: and the statement for each.
#   check_comma_statements.sh SOURCE_DIR    every .cpp, .h and .glsl file of the course tree
#   check_comma_statements.sh FILE...
set -euo pipefail
[ $# -gt 0 ] || { echo "usage: check_comma_statements.sh SOURCE_DIR | FILE..."; exit 2; }
if [ $# -eq 1 ] && [ -d "$1" ]; then
  mapfile -t files < <(cd "$1" && find framework stages grader tools shaders -name node_modules -prune -o \
                         -type f \( -name '*.cpp' -o -name '*.h' -o -name '*.glsl' \) -print 2> /dev/null | sort)
  [ ${#files[@]} -gt 0 ] || { echo "no C++ or GLSL files under $1"; exit 1; }
  cd "$1"
  set -- "${files[@]}"
fi
awk '
function reset() { stmt = ""; comma = 0; start = 0; angle = 0 }
# The statement without its control-flow prefixes: if (...), for (...), while (...), switch (...),
# else, do, case labels.
function strip_control(s,    i, d, c) {
  for (;;) {
    sub(/^[ \t\n]+/, "", s)
    if (match(s, /^(else|do)([^A-Za-z0-9_]|$)/)) { s = substr(s, RLENGTH); continue }
    if (match(s, /^(case [^:]*|default|[A-Za-z_][A-Za-z0-9_]*):([^:]|$)/)) {
      s = substr(s, RLENGTH); continue
    }
    if (!match(s, /^(if|for|while|switch)[ \t\n]*\(/)) return s
    d = 0
    for (i = RLENGTH; i <= length(s); i++) {
      c = substr(s, i, 1)
      if (c == "(") d++
      else if (c == ")" && --d == 0) break
    }
    s = substr(s, i + 1)
  }
}
function report(    s) {
  if (comma && !in_enum[braces]) {
    s = strip_control(stmt)
    if (s ~ /^[A-Za-z_][A-Za-z0-9_]*((\.|->)[A-Za-z_][A-Za-z0-9_]*|\[[^]]*\])*[ \t\n]*([-+*\/%&|^]|<<|>>)?=[^=]/ ||
        s ~ /^(\+\+|--)/ || s ~ /^[A-Za-z_][A-Za-z0-9_.]*(\+\+|--)/) {
      gsub(/[ \t\n]+/, " ", s)
      printf "%s:%d: %s;\n", FILENAME, start, substr(s, 1, 120)
      found++
    }
  }
  reset()
}
FNR == 1 { state = "code"; depth = 0; braces = 0; delete in_enum; reset() }
{
  line = $0 "\n"
  n = length(line)
  for (i = 1; i <= n; i++) {
    c = substr(line, i, 1)
    if (state == "block") { if (c == "*" && substr(line, i + 1, 1) == "/") { state = "code"; i++ } continue }
    if (state == "string") { if (c == "\\") i++; else if (c == "\"") state = "code"; continue }
    if (state == "char") { if (c == "\\") i++; else if (c == "\047") state = "code"; continue }
    if (state == "raw") { if (substr(line, i, length(raw_end)) == raw_end) { state = "code"; i += length(raw_end) - 1 } continue }
    if (c == "/" && substr(line, i + 1, 1) == "/") break
    if (c == "/" && substr(line, i + 1, 1) == "*") { state = "block"; i++; continue }
    if (c == "R" && substr(line, i + 1, 1) == "\"" && substr(line, i - 1, 1) !~ /[A-Za-z0-9_]/) {
      rest = substr(line, i + 2)
      raw_end = ")" substr(rest, 1, index(rest, "(") - 1) "\""
      state = "raw"; i += index(rest, "("); continue
    }
    if (c == "\"") { state = "string"; stmt = stmt "\"\""; continue }
    if (c == "\047" && substr(line, i - 1, 1) !~ /[0-9A-Fa-f]/) { state = "char"; stmt = stmt "0"; continue }
    if (c == "#" && stmt ~ /^[ \t\n]*$/) break  # a preprocessor line
    if (start == 0 && c !~ /[ \t\n]/) start = FNR
    # A template argument list: `<` right after a name (clang-format puts spaces around a
    # comparison), closed by `>` (not the `>` of `->`).
    if (c == "<" && substr(line, i - 1, 1) ~ /[A-Za-z0-9_]/) angle++
    else if (c == ">" && angle > 0 && substr(line, i - 1, 1) != "-") angle--
    if (c == "(" || c == "[") depth++
    else if (c == ")" || c == "]") depth--
    else if (depth == 0 && angle == 0 && c == ",") comma = 1
    if (depth == 0 && (c == ";" || c == "{" || c == "}")) {
      if (c == "{") { enum_block = stmt ~ /(^|[^A-Za-z0-9_])enum([^A-Za-z0-9_]|$)/ || in_enum[braces] }
      report()
      if (c == "{") in_enum[++braces] = enum_block
      else if (c == "}" && braces > 0) braces--
      continue
    }
    stmt = stmt c
  }
}
END {
  if (found) { printf "%d comma-chained statements: write each statement on its own line\n", found; exit 1 }
  print "no comma-chained statements"
}' "$@"
