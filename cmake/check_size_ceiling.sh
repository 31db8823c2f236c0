#!/usr/bin/env bash
# Tree.SizeCeilingFails: cmake/check_sizes.sh must fail a 1001-line file, saying why.
#   cmake/check_size_ceiling.sh SOURCE_DIR
set -uo pipefail
dir="$(mktemp -d)"
trap 'rm -r "$dir"' EXIT
seq 1001 > "$dir/long.cpp"
out="$(bash "$1/cmake/check_sizes.sh" "$dir")"
status=$?
echo "$out"
if (( status != 1 )); then
    echo "FAIL: check_sizes.sh exited $status on a 1001-line file (expected 1)"
    exit 1
fi
grep -q "^error: long.cpp: the file is 1001 lines" <<< "$out" ||
    { echo "FAIL: check_sizes.sh did not name long.cpp's 1001 lines"; exit 1; }
