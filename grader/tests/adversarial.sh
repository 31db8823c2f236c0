#!/usr/bin/env bash
# One case of the adversarial suite: builds a hostile submission from the instructor's
# solution (so the cases follow the course as it changes), grades it with rt-grade and checks
# that the grader finished, contained the code and scored it as expected.
#   adversarial.sh BIN_DIR SRC_DIR CASE
set -uo pipefail
bin=$1 src=$2 case=$3
work=$(mktemp -d /tmp/rt-grade-adv-XXXXXX)
trap 'rm -rf "$work"' EXIT
sub=$work/submission
s1=stages/01-camera-rays s2=stages/02-intersections
mkdir -p "$sub/$s1" "$sub/$s2"

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

# Whole-command cases: batch mode, the Gradescope package, an interrupted grading.
case $case in
  batch)  # two submissions, one a broken zip: both get a row, the batch finishes
    mkdir -p "$work/all/good/$s1"
    cp "$src/$s1/camera_rays.cpp" "$work/all/good/$s1/"
    echo "not a zip" > "$work/all/broken.zip"
    "$bin/rt-grade" batch "$work/all" --out "$work/grades" --jobs 1 --stages 1 || exit 1
    cat "$work/grades/scores.csv"
    grep -q '^"good",18,18' "$work/grades/scores.csv" || { echo "FAIL: good row"; exit 1; }
    grep -q '^"broken",0,18' "$work/grades/scores.csv" || { echo "FAIL: broken row"; exit 1; }
    "$bin/results_check" "$work/grades/broken/results.json" --contains "not a readable zip" || exit 1
    [ -s "$work/grades/good/report.html" ] || { echo "FAIL: no report"; exit 1; }
    exit 0 ;;
  package)
    "$bin/rt-grade" package --out "$work/autograder.zip" --source "$src" || exit 1
    unzip -l "$work/autograder.zip" > "$work/list" || exit 1
    for f in setup.sh run_autograder source/CMakeLists.txt source/scripts/install-deps.sh \
             source/stages/02-intersections/hidden/hidden_test.cpp; do
      grep -q " $f\$" "$work/list" || { echo "FAIL: $f missing from the zip"; exit 1; }
    done
    if grep -q " source/build" "$work/list"; then echo "FAIL: build tree in the zip"; exit 1; fi
    exit 0 ;;
  interrupted)  # SIGTERM while a test hangs: results.json is still written, tests listed
    cp "$src/$s1/camera_rays.cpp" "$sub/$s1/"
    echo 'namespace { struct Spin { Spin() { volatile bool f = true; while (f) {} } } spin; }' \
      >> "$sub/$s1/camera_rays.cpp"
    "$bin/rt-grade" "$sub" --stages 1 --time-limit 60 --quiet --results "$work/results.json" &
    pid=$!
    for _ in $(seq 300); do grep -q "grading did not finish" "$work/results.json" 2>/dev/null && break; sleep 1; done
    sleep 5
    kill -TERM $pid; wait $pid
    "$bin/results_check" "$work/results.json" --score-max 0 --max-score 18 \
      --contains "Grading was interrupted" || exit 1
    exit 0 ;;
esac

stages=1
limit=(--time-limit 2)  # stage 01 only: hostile cases time out fast
checks=()
# The degraded sandbox (as where Docker forbids namespaces): a crash is still contained and
# reported, and the report says which isolation was used.
if [ $case = uid_segfault ]; then
  export RT_GRADE_ISOLATION=uid
  case=segfault
  checks=(--contains "Sandbox: ")
  [ "$(id -u)" -eq 0 ] && checks+=(--contains "uid drop to nobody")
fi
case $case in
  reference)  # the instructor's own files: full marks
    solution1; solution2; stages=1,2; limit=()
    checks=(--score-min 83 --max-score 83) ;;
  starter)  # the released stubs: 0 points, and the report names the handout sections
    stub "$src/$s1/camera_rays.cpp" > "$sub/$s1/camera_rays.cpp"
    stub "$src/$s2/intersections.cpp" > "$sub/$s2/intersections.cpp"; stages=1,2; limit=()
    checks=(--score-max 0 --max-score 83
            --contains "Read the handout: stages/01-camera-rays/README.md#perspective-rays"
            --contains "Read the handout: stages/02-intersections/README.md#ray-sphere") ;;
  compile_error)
    solution1; echo 'int broken = ;' | append1
    checks=(--score-max 0 --max-score 18 --contains "Build (compiling your files)"
            --contains "camera_rays.cpp" --contains "not run: the build failed") ;;
  infinite_loop)
    solution1
    append1 <<'CPP'
namespace { struct Spin { Spin() { volatile bool forever = true; while (forever) {} } } spin; }
CPP
    checks=(--score-max 0 --contains "timed out after 2 s") ;;
  fork_bomb)
    solution1
    append1 <<'CPP'
#include <unistd.h>
namespace { struct Bomb { Bomb() { for (;;) fork(); } } bomb; }
CPP
    checks=(--score-max 0) ;;
  memory_hog)
    solution1
    append1 <<'CPP'
#include <cstring>
#include <vector>
namespace { struct Hog { Hog() {
  std::vector<char*> blocks;
  for (int i = 0; i < 256; ++i) { char* b = new char[64 << 20]; std::memset(b, 1, 64 << 20); blocks.push_back(b); }
} } hog; }
CPP
    checks=(--score-max 0 --contains "crashed: SIGABRT") ;;
  segfault)
    solution1
    append1 <<'CPP'
namespace { struct Crash { Crash() { volatile int* volatile p = nullptr; *p = 1; } } crash; }
CPP
    checks+=(--score-max 0 --contains "crashed: SIGSEGV") ;;
  output_flood)  # 1 GB of output
    solution1
    append1 <<'CPP'
#include <cstdio>
namespace { struct Flood { Flood() {
  static char line[1 << 20];
  for (auto& c : line) c = 'x';
  for (int i = 0; i < 1024; ++i) std::fwrite(line, 1, sizeof line, stdout);
} } flood; }
CPP
    checks=(--score-max 0 --contains "file size limit hit") ;;
  copy_reference)  # copies the reference image into the render output if it can read it
    solution1
    append1 <<'CPP'
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <unistd.h>
#include <vector>
namespace { struct Thief { Thief() {
  std::ifstream cmd("/proc/self/cmdline", std::ios::binary);
  std::string all((std::istreambuf_iterator<char>(cmd)), std::istreambuf_iterator<char>());
  std::vector<std::string> args;
  for (std::size_t p = 0, q; p < all.size(); p = q + 1) { q = all.find('\0', p); if (q == std::string::npos) q = all.size(); args.push_back(all.substr(p, q - p)); }
  if (args.size() < 5 || args[1] != "render") return;
  std::string out, scene = args[2];
  for (std::size_t i = 0; i + 1 < args.size(); ++i) if (args[i] == "-o") out = args[i + 1];
  std::string name = scene.substr(scene.rfind('/') + 1); name = name.substr(0, name.size() - 5);
  std::string here = __FILE__;
  std::vector<std::string> roots;
  if (auto c = here.find("/build/grader-cache/"); c != std::string::npos) roots.push_back(here.substr(0, c));
  if (auto c = here.find("/stages/"); c != std::string::npos) roots.push_back(here.substr(0, c));
  roots.push_back("/autograder/source");
  for (const auto& root : roots) {
    std::ifstream ref(root + "/reference_images/01-camera-rays/" + name + ".png", std::ios::binary);
    if (!ref) continue;
    std::ofstream(out, std::ios::binary) << ref.rdbuf();
    std::printf("REFERENCE COPIED from %s\n", root.c_str()); std::fflush(stdout);
    _exit(0);
  }
  std::printf("reference not readable\n"); std::fflush(stdout);
  _exit(3);
} } thief; }
CPP
    # Unit tests pass (10 points); every image fails because the copy was impossible.
    checks=(--score-min 10 --score-max 10 --not-contains "REFERENCE COPIED"
            --contains "reference not readable") ;;
  fake_results)  # writes a fake results.json where the grader will write its own
    solution1
    sed "s|@RESULTS@|$work/results.json|" <<'CPP' | append1
#include <fstream>
namespace { struct Forger { Forger() {
  std::ofstream("@RESULTS@") << R"({"score": 1000, "tests": [{"name": "FAKE", "score": 1000, "max_score": 1}]})";
} } forger; }
CPP
    checks=(--score-min 18 --score-max 18 --not-contains "FAKE") ;;
  edit_tests)  # edits tests and CMake files, plants a symlink and an odd name, submits stubs
    mkdir -p "$sub/$s1/tests"
    stub "$src/$s1/camera_rays.cpp" > "$sub/$s1/camera_rays.cpp"
    printf '#include <gtest/gtest.h>\nTEST(Perspective, CentreLooksAlongViewDirection) {}\n' \
      > "$sub/$s1/tests/camera_rays_test.cpp"
    echo 'message(FATAL_ERROR "edited")' > "$sub/$s1/CMakeLists.txt"
    echo 'project(evil)' > "$sub/CMakeLists.txt"
    ln -s /etc/passwd "$sub/$s1/notes.txt"
    echo x > "$sub/$s1/-rf"
    checks=(--score-max 0 --contains "edited course file" --contains "symbolic link"
            --contains "odd file name") ;;
  own_main)  # its own main: would replace GoogleTest's runner
    stub "$src/$s1/camera_rays.cpp" > "$sub/$s1/camera_rays.cpp"
    echo 'int main() { return 0; }' | append1
    checks=(--score-max 0 --contains "Build (compiling your files)") ;;
  test_symbols)  # redefines the fixture's stub check
    stub "$src/$s1/camera_rays.cpp" > "$sub/$s1/camera_rays.cpp"
    append1 <<'CPP'
#include "testing/stage_test.h"
void rt::testing::StageTest::TearDown() {}
CPP
    checks=(--score-max 0 --contains "Build (compiling your files)") ;;
  read_hidden)  # tries to read the hidden tests at run time (and passes its tests otherwise)
    solution2; stages=2; limit=()
    append2 <<'CPP'
#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>
namespace { struct Peek { Peek() {
  const std::string here = __FILE__;
  std::vector<std::string> candidates{here.substr(0, here.rfind('/')) + "/hidden/hidden_test.cpp"};
  if (auto c = here.find("/build/grader-cache/"); c != std::string::npos)
    candidates.push_back(here.substr(0, c) + "/stages/02-intersections/hidden/hidden_test.cpp");
  for (const auto& f : candidates)
    if (std::ifstream(f)) { std::printf("HIDDEN READABLE: %s\n", f.c_str()); std::fflush(stdout); _exit(4); }
} } peek; }
CPP
    checks=(--score-min 65 --score-max 65 --not-contains "HIDDEN READABLE") ;;
  include_hidden)  # tries to compile the hidden tests into its own code
    solution2; stages=2; limit=()
    echo '#include "hidden/hidden_test.cpp"' | append2
    checks=(--score-max 0 --contains "was not used" --contains "is not allowed") ;;
  # Calibration: the reference with other code generation must pass, known bugs must fail.
  calib_O0|calib_fast_math)
    [ $case = calib_O0 ] && pragma='#pragma GCC optimize("O0")' || pragma='#pragma GCC optimize("Ofast")'
    { echo "$pragma"; cat "$src/$s1/camera_rays.cpp"; } > "$sub/$s1/camera_rays.cpp"
    { echo "$pragma"; cat "$src/$s2/intersections.cpp"; } > "$sub/$s2/intersections.cpp"
    stages=1,2; limit=()
    if [ $case = calib_O0 ]; then checks=(--score-min 83 --max-score 83)
    # -Ofast assumes no NaN or Inf, so the two unit tests of NaN/Inf directions fail (the
    # conventions require those rays to miss); every image must still pass.
    else checks=(--test-passed "image" --score-min 81 --max-score 83); fi ;;
  calib_half_pixel)  # samples pixel corners instead of centres
    sed 's|Vec2 pixel, ImageSize size) {|Vec2 pixel, ImageSize size) {\n    pixel -= Vec2(0.5);|' \
      "$src/$s1/camera_rays.cpp" > "$sub/$s1/camera_rays.cpp"
    # The direction images are smooth gradients: half a pixel moves them by at most 2 levels,
    # within the tolerance, so the unit tests are what catches this bug (docs/grading.md).
    checks=(--test-failed "Perspective.PixelCentresAreSymmetric" --score-max 12) ;;
  calib_flipped_normals)  # stores the outward normal instead of the one facing the ray
    solution2; stages=2; limit=()
    grep -q 'set_face_normal' "$src/framework/core/hit.h" || { echo "hit.h changed"; exit 1; }
    cat >> "$sub/$s2/intersections.cpp" <<'CPP'
// (nothing appended: the bug is injected below)
CPP
    sed -i 's|hit.set_face_normal(ray, \(.*\));|hit.normal = \1; hit.front_face = true;|' "$sub/$s2/intersections.cpp"
    grep -q 'hit.front_face = true' "$sub/$s2/intersections.cpp" || { echo "no set_face_normal call to break"; exit 1; }
    # Only back faces show it: the triangle scene (spheres are seen from outside).
    checks=(--test-failed "image triangles_normals" --test-failed "Triangle.BackFaceIsHit") ;;
  *) echo "unknown case $case"; exit 2 ;;
esac

start=$(date +%s)
timeout 900 "$bin/rt-grade" "$sub" --stages "$stages" "${limit[@]}" --quiet \
  --results "$work/results.json" --html "$work/report.html"
code=$?
echo "rt-grade exited with $code after $(( $(date +%s) - start )) s"
[ $code -eq 0 ] || { echo "FAIL: rt-grade did not finish cleanly"; exit 1; }
[ -s "$work/report.html" ] || { echo "FAIL: no HTML report"; exit 1; }
if [ "$(id -u)" -eq 0 ] && pgrep -u 65534 >/dev/null; then
  echo "FAIL: processes of the sandbox user survived:"; pgrep -a -u 65534; exit 1
fi
"$bin/results_check" "$work/results.json" "${checks[@]}" || {
  echo "--- results.json"; head -c 6000 "$work/results.json"; exit 1; }
