#!/usr/bin/env bash
# `rt-grade batch --slurm` without a cluster (CTest: Grader.Slurm.scripts, in CI; the cluster
# itself is Grader.Slurm.class): --slurm-no-submit writes the manifest and both scripts, with
# --mem and the array set; a task grades its manifest line; the collector writes scores.csv, names
# the tasks that left no row with the command that reruns them, and exits 1 until they have
# run; and each misuse is one line naming the fix.
#   slurm_scripts.sh BIN_DIR SRC_DIR
set -u -o pipefail
bin=$1 src=$(cd "$2" && pwd) case=slurm_scripts
source "$(dirname "$0")/case_lib.sh"
fail() { echo "FAIL: $*"; exit 1; }

# expect_error WORDS COMMAND...: COMMAND fails with one line holding WORDS.
expect_error() {
  local words=$1
  shift
  "$@" > "$work/err" 2>&1 && fail "$* succeeded"
  grep -q -- "$words" "$work/err" || { cat "$work/err"; fail "$* does not say '$words'"; }
}

mkdir -p "$work/class/ann/$s1" "$work/class/bob/$s1" "$work/class/.hidden"
cp "$src/$s1/camera_rays.cpp" "$work/class/ann/$s1/"
stub "$src/$s1/camera_rays.cpp" > "$work/class/bob/$s1/camera_rays.cpp"
grades=$work/grades
"$bin/rt-grade" batch "$work/class" --out "$grades" --stages 1 --slurm --slurm-no-submit \
  --source "$src" > "$work/log" 2>&1 || { cat "$work/log"; fail "batch --slurm --slurm-no-submit"; }
grep -q "sbatch --parsable $grades/.slurm/grade.sbatch" "$work/log" || { cat "$work/log"; fail "no submit command"; }
[ "$(jq '.submissions | length' "$grades/.slurm/manifest.json")" = 2 ] || fail "not two submissions (the hidden folder is none)"
[ "$(jq -r '.submissions[1].name' "$grades/.slurm/manifest.json")" = bob ] || fail "manifest order"
for line in '#SBATCH --array=0-1' '#SBATCH --mem=2G' '#SBATCH --cpus-per-task=1' '#SBATCH --time=8' 'slurm-task'; do
  grep -q -- "$line" "$grades/.slurm/grade.sbatch" || { cat "$grades/.slurm/grade.sbatch"; fail "grade.sbatch lacks $line"; }
done
grep -q -- 'slurm-collect' "$grades/.slurm/collect.sbatch" || fail "collect.sbatch does not collect"

# Task 1 alone (as sbatch --array=1 would run it), then the collector with task 0 missing.
"$bin/rt-grade" slurm-task "$grades" 1 > "$work/task.log" 2>&1 || { cat "$work/task.log"; fail "slurm-task 1"; }
grep -q '^bob: 0 / ' "$work/task.log" || { cat "$work/task.log"; fail "task 1 did not grade bob"; }
"$bin/rt-grade" slurm-collect "$grades" > "$work/collect.log" 2>&1 && fail "the collector succeeded with task 0 missing"
grep -q "sbatch --parsable --array=0 " "$work/collect.log" || { cat "$work/collect.log"; fail "no rerun command for task 0"; }
grep -q '^"ann",0,0,,"grader error: its Slurm task did not finish"$' "$grades/scores.csv" || { cat "$grades/scores.csv"; fail "ann's row"; }
"$bin/rt-grade" slurm-task "$grades" 0 > "$work/task.log" 2>&1 || { cat "$work/task.log"; fail "slurm-task 0"; }
"$bin/rt-grade" slurm-collect "$grades" > "$work/collect.log" 2>&1 || { cat "$work/collect.log"; fail "the collector"; }
max=$(stage_points 1)
grep -q "^\"ann\",$max,$max,$max,\"ok\"$" "$grades/scores.csv" && grep -q "^\"bob\",0,$max,0,\"ok\"$" "$grades/scores.csv" ||
  { cat "$grades/scores.csv"; fail "scores.csv after both tasks"; }
[ -s "$grades/index.html" ] || fail "no dashboard"
grep -q "\.slurm" "$grades/index.html" && fail "the dashboard lists .slurm"

# Misuse: one line each.
expect_error "goes with --slurm" "$bin/rt-grade" batch "$work/class" --out "$work/x" --slurm-no-submit
mkdir -p "$work/with space"
expect_error "space or quote" "$bin/rt-grade" batch "$work/class" --out "$work/with space/g" --slurm --slurm-no-submit
expect_error "not a line of the manifest (0 to 1)" "$bin/rt-grade" slurm-task "$grades" 7
expect_error "run the batch with --slurm again" "$bin/rt-grade" slurm-task "$work/class" 0
expect_error "run the batch with --slurm again" "$bin/rt-grade" slurm-collect "$work/class"
echo "ok: scripts written, tasks graded by manifest line, the collector names a missing task"
