#!/usr/bin/env bash
# No two framework folders include each other, directly or round a longer loop
# (docs/architecture.md#folders): each folder can then be read, and tested, knowing only the
# folders below it. tsort (coreutils) finds the loops.
#   check_folder_cycles.sh FRAMEWORK_DIR
set -euo pipefail
cd "$1"
edges=$(grep -rHoE '^#include "[a-z_]+/' --include='*.h' --include='*.cpp' \
            --exclude-dir=tests . \
        | sed -E 's|^\./([a-z_]+)/[^:]*:#include "([a-z_]+)/$|\1 \2|' \
        | awk '$1 != $2' | sort -u)
[[ -n "$edges" ]] || { echo "FAIL: no includes between framework folders found in $1"; exit 1; }
if ! out=$(tsort <<< "$edges" 2>&1 >/dev/null) || [[ -n "$out" ]]; then
    echo "FAIL: framework folders include each other in a loop (tsort names its folders):"
    echo "$out"
    echo "Move the code that needs both folders into the higher one (docs/architecture.md#folders)."
    exit 1
fi
echo "ok: $(wc -l <<< "$edges") include edges between $(tr ' ' '\n' <<< "$edges" | sort -u | wc -l) framework folders, no loop"
