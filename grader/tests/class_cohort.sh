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
exp=$work/export/assignment_61_export
n=0 metadata=""

# submission NAME SID SCORE MINUTES: a new submission folder of NAME (its files go in $dir),
# made MINUTES after 09:00 on 2026-12-01, scored SCORE by Gradescope before the regrade.
submission() {
  n=$((n + 1)); dir=$exp/submission_$n; mkdir -p "$dir"
  metadata+="submission_$n:
  :submitters:
  - :name: $1
    :sid: '$2'
    :email: $(tr 'A-Z ' 'a-z.' <<< "$1")@example.com
  :created_at: 2026-12-01 $(printf '%02d:%02d' $((9 + $4 / 60)) $(($4 % 60))):00.000000000 -0800
  :score: $3
"
}
ref1() { cp "$src/$s1/camera_rays.cpp" "$dir/"; }
ref2() { cp "$src/$s2/intersections.cpp" "$dir/"; }
stub1() { stub "$src/$s1/camera_rays.cpp" > "$dir/camera_rays.cpp"; }
stub2() { stub "$src/$s2/intersections.cpp" > "$dir/intersections.cpp"; }

build_class() {
  submission "Ada Byron" 101 10 0;        stub1; stub2   # her first try, replaced by the next
  submission "Ada Byron" 101 84 90;       ref1; ref2
  submission "Bo Chen" 102 84 10;         ref1; disguise "$src/$s2/intersections.cpp" > "$dir/intersections.cpp"
  submission "Ivo Petrov" 103 84 20;      ref1
  disguise "$src/$s2/intersections.cpp" | sed 's/\bspan\b/window/g; s/\bdisc\b/delta/g' > "$dir/intersections.cpp"
  submission "Cy Young" 104 84 30;        ref1; cp "$src/$s2/hidden/similarity_independent.cpp" "$dir/intersections.cpp"
  submission "Dee Okafor" 105 0 40;       stub1; stub2
  submission "Eve Adams" 106 18 50;       ref1                       # stage 02 not handed in
  submission "Fay Wong" 107 70 60;        ref2                       # pixel corners, not centres
  sed 's|Vec2 pixel, ImageSize size) {|Vec2 pixel, ImageSize size) {\n    pixel -= Vec2(0.5);|' \
    "$src/$s1/camera_rays.cpp" > "$dir/camera_rays.cpp"
  submission "Gus Lind" 108 76 70;        ref1                       # normals not flipped to the ray
  sed 's|hit.set_face_normal(ray, \(.*\));|hit.normal = \1; hit.front_face = true;|' \
    "$src/$s2/intersections.cpp" > "$dir/intersections.cpp"
  submission "Hal Berg" 109 18 80;        ref1; { ref2; echo 'int broken = ;' >> "$dir/intersections.cpp"; }
  submission "Jo Marsh" 110 66 100;       stub1; ref2
  submission "Kim Sato" 111 0 110;        stub1                      # a start, nothing more
  submission "Lu Diaz" 112 "" 120;        ref1; ref2                 # not yet scored by Gradescope
  printf '%s' "$metadata" > "$exp/submission_metadata.yml"
  (cd "$work/export" && zip -q -r ../export.zip .) || fail "zip the export"
}

check_grades() {
  local csv=$out/scores.csv
  [[ -f $csv && -f $out/changes.csv && -f $out/index.html ]] || fail "missing output in $out"
  [[ $(($(wc -l < "$csv") - 1)) -eq 12 ]] || { cat "$csv"; fail "scores.csv: not 12 rows"; }
  head -1 "$csv" | grep -q '^submission,student,sid,email,score,max_score,stage01,stage02,status,seconds,old_score,change$' ||
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

build_class
"$bin/rt-grade" batch "$work/export.zip" --latest --out "$out" --stages 1,2 --jobs 2 \
  --source "$src" > "$work/batch.log" 2>&1 || { cat "$work/batch.log"; fail "rt-grade batch"; }
check_grades
check_similarity
