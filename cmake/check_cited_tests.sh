#!/usr/bin/env bash
# Docs.CitedTestsExist: every test name a handout or doc cites in backticks
# (`Sphere.SmallSphereFarAway`, `Stage02.ClosedMesh.*`, `Grader.Trust.network`) names at least
# one test `ctest -N` lists, so a student who runs `ctest -R` on it finds it. A name matches a test whose name is it, ends with
# "." and it, or starts with it and "." or "/"; `*` matches anything. Names with a placeholder
# (`<binary>`, `stageNN`) are skipped.
#   check_cited_tests.sh BUILD_DIR FILE...
set -euo pipefail
build=$1
shift
tests=$(ctest --test-dir "$build" -N | sed -n 's/^ *Test *#[0-9]*: //p')
[ -n "$tests" ] || { echo "ctest -N listed no tests in $build"; exit 1; }
pattern='`[A-Z][A-Za-z0-9]+(/[A-Za-z0-9]+)?\.[A-Z][A-Za-z0-9_/*]+(\.[A-Za-z0-9_/*]+)?`'
missing=0 checked=0
for file in "$@"; do
  while IFS=: read -r line cited; do
    name=${cited//\`/}
    case $name in *'<'* | *NN*) continue ;; esac
    checked=$((checked + 1))
    regex=$(printf '%s' "$name" | sed 's/[.[\^$+?(){}|]/\\&/g; s/\*/.*/g')
    if ! grep -qE "^(.*\.)?$regex([./].*)?$" <<< "$tests"; then
      echo "$file:$line: cites test $name, which ctest -N does not list"
      missing=$((missing + 1))
    fi
  done < <(grep -noE "$pattern" "$file" | sed 's/:/:/')
done
[ "$missing" -eq 0 ] || exit 1
echo "all $checked cited test names exist"
