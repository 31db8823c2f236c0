#!/usr/bin/env bash
# Class-size figures (docs/grading.md, "Class-size figures"): a synthetic class of N submissions
# of stage 01 (the reference, the starter, a planted bug, a compile error and a disguised copy,
# in turn) graded by a local `rt-grade batch --jobs 2` and by `batch --slurm` on a one-machine
# cluster started here (grader/tests/slurm_local.sh); then the dashboard and the similarity
# report of N and of M submissions. Prints seconds and peak memory of each. Root; minutes.
#   sudo tools/class_size.sh [--grade 300] [--report 1000] [--rt-grade BIN] [--keep DIR]
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
grade_n=300 report_n=1000 rt_grade=$src/build/bin/rt-grade keep=""
while [ $# -gt 0 ]; do
  case $1 in
    --grade) grade_n=$2; shift 2 ;;
    --report) report_n=$2; shift 2 ;;
    --rt-grade) rt_grade=$2; shift 2 ;;
    --keep) keep=$2; shift 2 ;;
    -h | --help) sed -n '2,7p' "$0"; exit 0 ;;
    *) echo "class_size: error: unknown option $1 (see --help)" >&2; exit 2 ;;
  esac
done
[ -x "$rt_grade" ] || { echo "class_size: error: $rt_grade is not built: cmake --build build --target rt-grade" >&2; exit 2; }
work=${keep:-$(mktemp -d /var/tmp/rt-class-size-XXXXXX)}
mkdir -p "$work"
source "$src/grader/tests/slurm_local.sh"
source "$src/grader/tests/disguise.sh"
source "$src/grader/tests/stub.sh"  # stub FILE: the starter version of a student file
trap 'slurm_stop; [ -n "$keep" ] || rm -rf "$work"' EXIT
trap 'exit 1' INT TERM  # so that EXIT's trap stops the daemons
s1=stages/01-camera-rays
ref=$src/$s1/camera_rays.cpp

# One submission folder per student, five kinds in turn.
make_class() {
  local n=$1 dir=$2 i
  for i in $(seq 1 "$n"); do
    mkdir -p "$dir/student_$i"
    case $((i % 5)) in
      0) cp "$ref" "$dir/student_$i/" ;;
      1) stub "$ref" > "$dir/student_$i/camera_rays.cpp" ;;
      2) sed 's|Vec2 pixel, ImageSize size) {|Vec2 pixel, ImageSize size) {\n    pixel -= Vec2(0.5);|' "$ref" \
           > "$dir/student_$i/camera_rays.cpp" ;;
      3) { cat "$ref"; echo 'int broken = ;'; } > "$dir/student_$i/camera_rays.cpp" ;;
      4) disguise "$ref" > "$dir/student_$i/camera_rays.cpp" ;;
    esac
  done
}

# measure LABEL COMMAND...: wall seconds and peak resident MB (GNU time) of COMMAND.
measure() {
  local label=$1
  shift
  /usr/bin/time -f "%e %M" -o "$work/time" "$@" > "$work/$label.log" 2>&1 ||
    { tail -n 20 "$work/$label.log"; echo "class_size: $label failed" >&2; return 1; }
  read -r wall kb < "$work/time"
  printf '%-34s %8.1f s %8d MB\n' "$label" "$wall" $((kb / 1024))
}

"$rt_grade" prepare --source "$src" > /dev/null
make_class "$grade_n" "$work/class"
echo "class of $grade_n submissions of stage 01 ($work/class)"
measure "local batch --jobs 2" "$rt_grade" batch "$work/class" --out "$work/local" --stages 1 --jobs 2 --source "$src"
echo "  per submission: $(awk -v w="$wall" -v n="$grade_n" 'BEGIN { printf "%.2f", w / n }') s"

slurm_start "$work/cluster"
start=$(date +%s.%N)
"$rt_grade" batch "$work/class" --out "$work/slurm" --stages 1 --slurm --source "$src" > "$work/slurm.log"
collector=$(sed -n 's/^slurm: job \([0-9]*\) writes.*/\1/p' "$work/slurm.log")
slurm_wait_done "$collector" 7200
wall=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.1f", e - s }')
graded=$(cat "$work/slurm/.slurm/rows/"*.json | jq -s 'map(.seconds) | add')
echo "slurm array of $grade_n tasks, 2 CPUs: $wall s; grading inside the tasks $graded s"
awk -v w="$wall" -v g="$graded" -v n="$grade_n" -v c="$(nproc)" \
  'BEGIN { printf "  per submission: %.2f s; overhead per task (CPU-seconds beyond grading): %.2f s\n", w / n, (w * c - g) / n }'
cmp -s "$work/local/scores.csv" "$work/slurm/scores.csv" && echo "  scores.csv identical to the local batch's" ||
  echo "  scores.csv DIFFERS from the local batch's"

for n in "$grade_n" "$report_n"; do
  # The dashboard reads results.json files: the graded class's, copied around to n folders.
  mkdir -p "$work/dash$n"
  for i in $(seq 1 "$n"); do
    mkdir -p "$work/dash$n/student_$i"
    cp "$work/local/student_$(( (i - 1) % grade_n + 1 ))/results.json" "$work/dash$n/student_$i/"
  done
  measure "dashboard of $n" "$rt_grade" dashboard "$work/dash$n" --source "$src"
  [ -d "$work/class$n" ] || make_class "$n" "$work/class$n"
  measure "similarity report of $n" "$rt_grade" similarity "$work/class$n" --out "$work/sim$n" --stages 1 --source "$src"
  echo "  index.html $(du -k "$work/dash$n/index.html" | cut -f1) KB; similarity index.html $(du -k "$work/sim$n/index.html" | cut -f1) KB"
done
