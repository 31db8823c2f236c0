# Shared by the grader's case scripts (adversarial.sh, trust.sh): a scratch folder, the
# stage files, helpers that build submissions from the instructor's solution, and the final
# grade-and-check step. Source it after setting bin, src and case.
work=$(mktemp -d /tmp/rt-grade-adv-XXXXXX)
trap 'rm -rf "$work"' EXIT
sub=$work/submission
s1=stages/01-camera-rays s2=stages/02-intersections s3=stages/03-blinn-phong
s4=stages/04-shadows s5=stages/05-recursion s6=stages/06-bvh s7=stages/07-textures
s8=stages/08-environment s9=stages/09-gpu s10=stages/10-sampling
mkdir -p "$sub/$s1" "$sub/$s2"
# Every graded stage (a grading.json) and its student files, from the course manifest, so the
# cases follow the course as it changes (stage 09's are GLSL, graded on the GPU).
all_stages=$(for g in "$src"/stages/[0-9][0-9]-*/grading.json; do
               d=$(basename "$(dirname "$g")"); echo $((10#${d:0:2})); done | paste -sd,)
mapfile -t files < <(for g in "$src"/stages/[0-9][0-9]-*/grading.json; do
                       d=stages/$(basename "$(dirname "$g")")
                       jq -r --arg d "$d" '.student_files[] | "\($d)/\(.)"' "$src/$d/stage.json"; done)
[[ -n $all_stages && ${#files[@]} -gt 0 ]] || { echo "FAIL: no graded stage found under $src/stages"; exit 1; }
stage_tag() { printf 'stage%02d' "$1"; }  # results.json's tag of stage N
# Handout sections of the graded stubs. An optional part (a section named "#optional-...", such
# as stage 10's fog) is left out of grading.json, so no graded test reaches its stubs.
# C++ stubs name theirs in a string, GLSL ones in a comment after the call (GLSL has no strings).
sections() {
    { grep -ho 'RT_NOT_IMPLEMENTED("[^"]*")' "${files[@]/#/$src/}" | sed 's/.*("\(.*\)")/\1/'
      grep -ho 'RT_NOT_IMPLEMENTED(); *// [^ ]*' "${files[@]/#/$src/}" | sed 's|.*// ||'
    } | grep -v '#optional-' | sort -u
}

source "$(dirname "${BASH_SOURCE[0]}")/stub.sh"  # stub FILE: the starter version
solution1() { cp "$src/$s1/camera_rays.cpp" "$sub/$s1/camera_rays.cpp"; }
solution2() { cp "$src/$s2/intersections.cpp" "$sub/$s2/intersections.cpp"; }
append1() { cat >> "$sub/$s1/camera_rays.cpp"; }
append2() { cat >> "$sub/$s2/intersections.cpp"; }
solution_all() { for f in "${files[@]}"; do mkdir -p "$sub/$(dirname "$f")"; cp "$src/$f" "$sub/$f"; done; }


source "$(dirname "${BASH_SOURCE[0]}")/stage_points.sh"

# A row of a batch's scores.csv that starts "NAME",SCORE,MAX, with SCORE as given ("max": full marks) and MAX
# the points of stage 1.
expect_row() {
  local max score
  max=$(stage_points 1)
  score=$2; [[ $score == max ]] && score=$max
  grep -qE "^\"$1\",$score,$max(,|\$)" "$3" || { echo "FAIL: no row \"$1\",$score,$max in $3:"; cat "$3"; return 1; }
}

# Grades $sub (stages $stages, extra options in limit) and checks results.json with `checks`
# (where an argument @points stands for the points of the stages graded, known once graded).
grade_and_check() {
  local start code
  start=$(date +%s)
  timeout 900 "$bin/rt-grade" "$sub" --stages "$stages" "${limit[@]}" --quiet \
    --results "$work/results.json" --html "$work/report.html"
  code=$?
  echo "rt-grade exited with $code after $(( $(date +%s) - start )) s"
  [ $code -eq 0 ] || { echo "FAIL: rt-grade did not finish cleanly"; return 1; }
  [ -s "$work/report.html" ] || { echo "FAIL: no HTML report"; return 1; }
  # Survivors are looked for by the grader itself, per sandbox uid (never machine-wide).
  local expanded=() arg
  for arg in "${checks[@]}"; do
    [[ $arg == @points ]] && arg=$(for n in ${stages//,/ }; do stage_points "$n"; done | awk '{ t += $1 } END { print t }')
    expanded+=("$arg")
  done
  "$bin/results_check" "$work/results.json" --not-contains "outlived their test" "${expanded[@]}" || {
    echo "--- results.json"; head -c 6000 "$work/results.json"; return 1; }
}
