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
# Every stage that grading covers here, its student files, and the stubs' handout sections
# (stage 09's are GLSL, graded on the GPU).
all_stages=1,2,3,4,5,6,7,8,9,10
files=("$s1/camera_rays.cpp" "$s2/intersections.cpp" "$s3/blinn_phong.cpp" "$s4/shadows.cpp"
       "$s5/recursion.cpp" "$s6/bvh.cpp" "$s7/textures.cpp" "$s8/environment.cpp"
       "$s9/camera.glsl" "$s9/intersect.glsl" "$s9/bvh.glsl" "$s9/shade.glsl" "$s9/recursion.glsl"
       "$s9/textures.glsl" "$s9/environment.glsl" "$s10/sampling.cpp" "$s10/lights.cpp"
       "$s10/sampling.glsl")
stage_tag() { printf 'stage%02d' "$1"; }  # results.json's tag of stage N
# Handout sections of the graded stubs. An optional part (a section named "#optional-...", such
# as stage 10's fog) is left out of grading.json, so no graded test reaches its stubs.
sections() { grep -ho 'RT_NOT_IMPLEMENTED("[^"]*")' "${files[@]/#/$src/}" | sed 's/.*("\(.*\)")/\1/' | grep -v '#optional-' | sort -u; }

# The starter (stub) version of a student file: what `rt-grade release` writes.
stub() {
  awk '/^[ \t]*\/\/ BEGIN SOLUTION[ \t]*$/ {s=1; next}
       /^[ \t]*\/\/ STUB[ \t]*$/ {s=2; next}
       /^[ \t]*\/\/ END SOLUTION[ \t]*$/ {s=0; next}
       s==1 {next}
       s==2 {sub(/\/\/ ?/, "")}
       {print}' "$1"
}
solution1() { cp "$src/$s1/camera_rays.cpp" "$sub/$s1/camera_rays.cpp"; }
solution2() { cp "$src/$s2/intersections.cpp" "$sub/$s2/intersections.cpp"; }
append1() { cat >> "$sub/$s1/camera_rays.cpp"; }
append2() { cat >> "$sub/$s2/intersections.cpp"; }
solution_all() { for f in "${files[@]}"; do mkdir -p "$sub/$(dirname "$f")"; cp "$src/$f" "$sub/$f"; done; }


# Grades $sub (stages $stages, extra options in limit) and checks results.json with `checks`.
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
  "$bin/results_check" "$work/results.json" --not-contains "outlived their test" "${checks[@]}" || {
    echo "--- results.json"; head -c 6000 "$work/results.json"; return 1; }
}
