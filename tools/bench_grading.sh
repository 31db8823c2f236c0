#!/usr/bin/env bash
# Grading time per stage at Gradescope's limits (issue 51): the reference's student files graded
# one stage at a time by `rt-grade SUB --stages N --quiet` in a cgroup (v1) of half a CPU and
# 768 MB, the grading workspace prepared first (outside the cgroup). Prints one line a stage and
# the sum; asserts nothing (figures, not tests). Needs root (the cgroup and rt-grade's sandbox).
#   tools/bench_grading.sh [BUILD_DIR] [STAGES]       (defaults: build, every graded stage)
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$src/build}" && pwd)
[ "$(id -u)" -eq 0 ] || { echo "bench_grading: needs root (a cgroup, and rt-grade's sandbox)"; exit 1; }
cg=/sys/fs/cgroup
[ -d "$cg/cpu" ] && [ -d "$cg/memory" ] || { echo "bench_grading: needs cgroup v1's cpu and memory controllers"; exit 1; }

# The submission: every stage's student files from the instructor's tree (the reference).
sub=$(mktemp -d /tmp/rt-bench-grading-XXXXXX)
group=rt-bench-grading-$$
trap 'rmdir "$cg/cpu/$group" "$cg/memory/$group" 2> /dev/null || true; rm -rf "$sub"' EXIT
stages=()
for spec in "$src"/stages/[0-9][0-9]-*/grading.json; do
  dir=$(dirname "$spec")
  number=$(jq -r .number "$dir/stage.json")
  stages+=("$number")
  for f in $(jq -r '.student_files[]' "$dir/stage.json"); do
    mkdir -p "$sub/stages/$(basename "$dir")/$(dirname "$f")"
    cp "$dir/$f" "$sub/stages/$(basename "$dir")/$f"
  done
done
[ -n "${2:-}" ] && IFS=, read -r -a stages <<< "$2"
"$build/bin/rt-grade" prepare > /dev/null

mkdir -p "$cg/cpu/$group" "$cg/memory/$group"
period=$(cat "$cg/cpu/$group/cpu.cfs_period_us")
echo $((period / 2)) > "$cg/cpu/$group/cpu.cfs_quota_us"
echo $((768 * 1024 * 1024)) > "$cg/memory/$group/memory.limit_in_bytes"
echo "== $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), load $(cut -d' ' -f1-3 /proc/loadavg); half a CPU, 768 MB"
total=0
for n in "${stages[@]}"; do
  start=$(date +%s.%N)
  bash -c 'for g in "$1" "$2"; do echo $$ > "$g/cgroup.procs"; done; shift 2; exec "$@"' \
    _ "$cg/cpu/$group" "$cg/memory/$group" \
    "$build/bin/rt-grade" "$sub" --stages "$n" --quiet --results "$sub/results-$n.json" || true
  seconds=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN {printf "%.1f", e - s}')
  total=$(awk -v a="$total" -v b="$seconds" 'BEGIN {printf "%.1f", a + b}')
  echo "stage $(printf %02d "$n"): $seconds s, $(jq -r '"\(.score) of \([.tests[].max_score] | add) points"' "$sub/results-$n.json")"
done
echo "all: $total s; throttled in $(awk '/nr_throttled/ {t = $2} /nr_periods/ {p = $2} END {print t " of " p}' "$cg/cpu/$group/cpu.stat") periods"
