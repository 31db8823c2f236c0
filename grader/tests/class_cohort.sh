#!/usr/bin/env bash
# An instructor's view of a class (CTest: Grader.Class.cohort): thirteen submissions of stages 01
# and 02 laid out as Gradescope's "Export Submissions" (one folder each and
# submission_metadata.yml), graded with `rt-grade batch --latest` (twelve: one student submitted
# twice), then compared with `rt-grade similarity`. Requires: the dashboard (index.html with a
# histogram per stage and the tests worst first), scores.csv with the students' names and ids,
# changes.csv against Gradescope's old scores, and (among the submissions whose stage 02 has an
# author of its own) the disguised copies flagged first while the independent solution is not.
#   class_cohort.sh BIN_DIR SRC_DIR        (RT_COHORT_KEEP=DIR keeps the grades and the report)
set -u -o pipefail
bin=$1 src=$(cd "$2" && pwd) case=cohort
source "$(dirname "$0")/case_lib.sh"
source "$(dirname "$0")/disguise.sh"
fail() { echo "FAIL: $*"; exit 1; }
out=${RT_COHORT_KEEP:-$work/grades}
source "$(dirname "$0")/cohort_lib.sh"

check_grades() {
  local csv=$out/scores.csv
  [[ -f $csv && -f $out/changes.csv && -f $out/index.html ]] || fail "missing output in $out"
  [[ $(($(wc -l < "$csv") - 1)) -eq 12 ]] || { cat "$csv"; fail "scores.csv: not 12 rows"; }
  head -1 "$csv" | grep -q '^submission,student,sid,email,score,max_score,stage01,stage02,status,old_score,change$' ||
    fail "scores.csv header: $(head -1 "$csv")"
  grep -q '"Ada Byron","101"' "$csv" && ! grep -q '"submission_1"' "$csv" || fail "--latest kept Ada's first try"
  local full; full=$(jq -r '.tests | map(.max_score) | add' "$out/submission_2/results.json")
  grep '"submission_2"' "$csv" | grep -q ",$full,$full," || fail "Ada's solution lost points"
  grep '"submission_6"' "$csv" | grep -q ",0,$full," || fail "the starter scored"
  grep -q '"submission_13".*,new$' "$out/changes.csv" || fail "changes.csv: Lu's new score"
  local svgs; svgs=$(grep -c '<svg' "$out/index.html")
  [[ $svgs -ge 2 ]] || fail "index.html: $svgs histograms"
  grep -q '<td>Ada Byron (101)</td>' "$out/index.html" || fail "index.html: no students' names"
  grep -q 'Tests by failure rate' "$out/index.html" && grep -q 'Image tests by failure rate' "$out/index.html" ||
    fail "index.html: no failure-rate tables"
  echo "ok: 12 graded, scores.csv names the students, $svgs histograms, changes.csv"
}

# The similarity report on the submissions whose stage 02 has an author of its own: the class's
# other stage 02 files are the reference solution itself (this cohort has one independent
# solution to draw on), so they are copies of Ada's and would be rightly flagged.
check_similarity() {
  mkdir -p "$work/authors"
  for i in 2 3 4 5 6 7 12; do cp -r "$exp/submission_$i" "$work/authors/"; done
  "$bin/rt-grade" similarity "$work/authors" --out "$work/sim" --source "$src" --stages 2 \
    > /dev/null || fail "rt-grade similarity"
  local csv=$work/sim/pairs.csv
  # The top three pairs are the three among Ada and her two disguised copies (Bo, Ivo).
  sed -n 2,4p "$csv" | grep -c '"submission_\(2\|3\|4\)","submission_\(2\|3\|4\)"' | grep -qx 3 ||
    { head -6 "$csv"; fail "the copies are not ranked first"; }
  local indep
  indep=$(awk -F, '$2 == "\"submission_2\"" && $3 == "\"submission_5\"" { print $6 }' "$csv")
  (( ${indep:-0} < 50 )) || fail "the independent solution is flagged (${indep}%)"
  echo "ok: copies ranked first; the independent solution at ${indep:-0}%"
}

add_class
write_export
"$bin/rt-grade" batch "$work/export.zip" --latest --out "$out" --stages 1,2 --jobs 2 \
  --source "$src" > "$work/batch.log" 2>&1 || { cat "$work/batch.log"; fail "rt-grade batch"; }
check_grades
check_similarity
