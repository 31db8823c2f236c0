#!/usr/bin/env bash
# One case of the adversarial suite: builds a hostile submission from the instructor's
# solution (so the cases follow the course as it changes), grades it with rt-grade and checks
# that the grader finished, contained the code and scored it as expected.
#   adversarial.sh BIN_DIR SRC_DIR CASE
set -uo pipefail
bin=$1 src=$2 case=$3
source "$(dirname "$0")/case_lib.sh"

# Whole-command cases: batch mode, the Gradescope package run, an interrupted grading.
case $case in
  batch)  # two submissions, one a broken zip: both get a row, the batch finishes
    mkdir -p "$work/all/good/$s1"
    cp "$src/$s1/camera_rays.cpp" "$work/all/good/$s1/"
    echo "not a zip" > "$work/all/broken.zip"
    "$bin/rt-grade" batch "$work/all" --out "$work/grades" --jobs 1 --stages 1 || exit 1
    cat "$work/grades/scores.csv"
    expect_row good max "$work/grades/scores.csv" || exit 1
    expect_row broken 0 "$work/grades/scores.csv" || exit 1
    "$bin/results_check" "$work/grades/broken/results.json" --contains "not a readable zip" || exit 1
    [ -s "$work/grades/good/report.html" ] || { echo "FAIL: no report"; exit 1; }
    exit 0 ;;
  batch_export)  # a zipped export whose one submission unzip cannot unpack: only it is refused
    exp=$work/a/assignment_9_export
    mkdir -p "$exp/submission_1" "$exp/submission_2" "$work/b/assignment_9_export/submission_2/link"
    cp "$src/$s1/camera_rays.cpp" "$exp/submission_1/"
    cp "$src/$s1/camera_rays.cpp" "$exp/submission_2/"
    # A symbolic link, then a file written through it: unzip stops at the second entry.
    ln -s "$work/outside" "$exp/submission_2/link"
    echo planted > "$work/b/assignment_9_export/submission_2/link/planted.txt"
    for n in 1 2; do printf 'submission_%s:\n  :submitters:\n  - :name: Student %s\n    :sid: %s\n  :created_at: 2026-12-01 09:0%s:00.000000000 -0800\n' \
                      "$n" "$n" "$n" "$n"; done > "$exp/submission_metadata.yml"
    (cd "$work/a" && zip -q -r -y "$work/export.zip" .) || exit 1
    (cd "$work/b" && zip -q -r "$work/export.zip" assignment_9_export/submission_2/link/planted.txt) || exit 1
    "$bin/rt-grade" batch "$work/export.zip" --out "$work/grades" --jobs 1 --stages 1 || exit 1
    cat "$work/grades/scores.csv"
    grep -q '^"submission_1",.*,"ok",' "$work/grades/scores.csv" || { echo "FAIL: submission_1 not graded"; exit 1; }
    grep -q '^"submission_2",.*,0,[0-9]*,0,"refused: .*assignment_9_export/submission_2/link' "$work/grades/scores.csv" ||
      { echo "FAIL: submission_2 not refused with unzip's reason"; exit 1; }
    grep -q "/tmp/rt-grade-export" "$work/grades/scores.csv" && { echo "FAIL: a temporary path in scores.csv"; exit 1; }
    "$bin/results_check" "$work/grades/submission_2/results.json" --contains "could not be read" || exit 1
    [ ! -e "$work/outside" ] || { echo "FAIL: written through the link"; exit 1; }
    exit 0 ;;
  export_bomb)  # a zipped export with a zip bomb as one submission: only it is refused, unread
    exp=$work/a/assignment_9_export
    mkdir -p "$exp/submission_1" "$exp/submission_2"
    cp "$src/$s1/camera_rays.cpp" "$exp/submission_1/"
    cp "$src/$s1/camera_rays.cpp" "$exp/submission_2/"
    head -c 200M /dev/zero > "$exp/submission_2/zeros.bin"  # 200 MB, about 200 KB zipped
    for n in 1 2; do printf 'submission_%s:\n  :submitters:\n  - :name: Student %s\n    :sid: %s\n  :created_at: 2026-12-01 09:0%s:00.000000000 -0800\n' \
                      "$n" "$n" "$n" "$n"; done > "$exp/submission_metadata.yml"
    (cd "$work/a" && zip -q -r "$work/export.zip" .) || exit 1
    rm -rf "$work/a"
    "$bin/rt-grade" batch "$work/export.zip" --out "$work/grades" --jobs 1 --stages 1 || exit 1
    cat "$work/grades/scores.csv"
    grep -q '^"submission_1",.*,"ok",' "$work/grades/scores.csv" || { echo "FAIL: submission_1 not graded"; exit 1; }
    grep -q '^"submission_2",.*,0,[0-9]*,0,"refused: its files expand to 200 MB, more than the 64 MB' "$work/grades/scores.csv" ||
      { echo "FAIL: submission_2 not refused for its size"; exit 1; }
    # The bomb was never unpacked: no file of 64 MB or more anywhere the batch wrote.
    [ -z "$(find "$work" /tmp/rt-grade-export-* -size +65535k 2>/dev/null)" ] || { echo "FAIL: the bomb was unpacked"; exit 1; }
    exit 0 ;;
  package_run)  # the package's run_autograder in a simulated Gradescope layout
    # A package for an assignment of two stages, the first and the last: a complete submission
    # scores full marks in both, and the stages between are not graded (the reference case
    # grades every stage directly).
    root=$work/autograder
    first=${all_stages%%,*} last=${all_stages##*,}
    "$bin/rt-grade" package --out "$work/autograder.zip" --source "$src" --stages "$first,$last" > /dev/null || exit 1
    mkdir -p "$root/source" "$root/submission" "$root/results"
    (cd "$root/source" && unzip -q "$work/autograder.zip") || { echo "FAIL: unzip"; exit 1; }
    cp "$root/source/run_autograder" "$root/"  # where Gradescope puts it
    bash -n "$root/source/setup.sh" || { echo "FAIL: setup.sh does not parse"; exit 1; }
    [ -x "$root/run_autograder" ] || { echo "FAIL: run_autograder not executable"; exit 1; }
    # Gradescope unpacks the student's upload into submission/: here the loose files of every
    # graded stage (a complete submission; stages added later are graded too).
    for dir in "$src"/stages/*/; do
      [ -f "$dir/grading.json" ] || continue
      for f in $(jq -r '.student_files[]' "$dir/stage.json"); do cp "$dir/$f" "$root/submission/"; done
    done
    start=$(date +%s)
    RT_AUTOGRADER_ROOT=$root "$root/run_autograder" > "$work/run.log" 2>&1
    code=$?
    echo "run_autograder exited with $code after $(( $(date +%s) - start )) s"
    [ $code -eq 0 ] || { cat "$work/run.log"; echo "FAIL: run_autograder"; exit 1; }
    [ -s "$root/results/report.html" ] || { echo "FAIL: no report.html next to results.json"; exit 1; }
    checks=(--full-marks --full-marks-tag "$(stage_tag "$first")" --full-marks-tag "$(stage_tag "$last")")
    for n in ${all_stages//,/ }; do
      [[ $n == "$first" || $n == "$last" ]] || checks+=(--not-contains "$(printf 'Stage %02d ' "$n")")
    done
    "$bin/results_check" "$root/results/results.json" "${checks[@]}" --not-contains "not run" \
      --not-contains "is missing from the submission" || exit 1
    exit 0 ;;
  calib_no_gamma)  # images written without the sRGB transfer must fail every shaded scene
    failed=0 scenes=0
    for stage in 03-blinn-phong 04-shadows 05-recursion; do
      for name in $(jq -r '.scenes[].name' "$src/stages/$stage/grading.json"); do
        "$bin/rt" render "$src/stages/$stage/scenes/$name.json" -o "$work/$name.exr" -q || exit 1
        # Control: the same render, encoded as the writer does, passes (the check can fail).
        "$bin/rt-grade" compare --source "$src" --image "$work/$name.exr" --scene "$stage/$name" ||
          { echo "FAIL: the correct image of $stage/$name does not pass"; exit 1; }
        oiiotool "$work/$name.exr" -d uint8 -o "$work/$name.png" || exit 1  # linear -> 8 bit, no transfer
        scenes=$((scenes + 1))
        "$bin/rt-grade" compare --source "$src" --image "$work/$name.png" --scene "$stage/$name" &&
          { echo "FAIL: $stage/$name without gamma still gets full points"; failed=1; }
      done
    done
    [ $scenes -ge 3 ] || { echo "FAIL: no shaded scene"; exit 1; }
    exit $failed ;;
  interrupted)  # SIGTERM while a test hangs: results.json is still written, tests listed
    cp "$src/$s1/camera_rays.cpp" "$sub/$s1/"
    echo 'namespace { struct Spin { Spin() { volatile bool f = true; while (f) {} } } spin; }' \
      >> "$sub/$s1/camera_rays.cpp"
    "$bin/rt-grade" "$sub" --stages 1 --time-limit 60 --quiet --results "$work/results.json" &
    pid=$!
    for _ in $(seq 300); do grep -q "grading did not finish" "$work/results.json" 2>/dev/null && break; sleep 1; done
    sleep 5
    kill -TERM $pid; wait $pid
    "$bin/results_check" "$work/results.json" --score-max 0 --max-score "$(stage_points 1)" \
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
  [ "$(id -u)" -eq 0 ] && checks+=(--contains "uid drop to a sandbox uid")
fi
case $case in
  reference)  # the instructor's own files: full marks in every stage
    solution_all; stages=$all_stages; limit=()
    checks=(--full-marks --not-contains "not run" --has-leaderboard
            --leaderboard-first "Traversal cost per ray")
    for n in ${all_stages//,/ }; do checks+=(--has-tag "$(stage_tag "$n")"); done ;;
  starter)  # the released starter tree: 0 points, and the report names every stub's section
    "$bin/rt-grade" release --source "$src" --out "$work/starter" > /dev/null || exit 1
    sub=$work/starter; stages=$all_stages; limit=()
    checks=(--score-max 0 --no-leaderboard)
    for n in ${all_stages//,/ }; do checks+=(--has-tag "$(stage_tag "$n")"); done
    while read -r section; do checks+=(--contains "Read the handout: $section"); done < <(sections)
    [ ${#checks[@]} -gt 12 ] || { echo "FAIL: no stub section found"; exit 1; } ;;
  compile_error)
    solution1; echo 'int broken = ;' | append1
    checks=(--score-max 0 --max-score @points --contains "Build (compiling your files)"
            --contains "camera_rays.cpp" --contains "not run: the build failed") ;;
  infinite_loop)
    solution1
    append1 <<'CPP'
namespace { struct Spin { Spin() { volatile bool forever = true; while (forever) {} } } spin; }
CPP
    # Spinning is work: the CPU limit stops it (the wall clock is for a child that waits). Every
    # process of the stage spins to its limit, so one second each keeps the case short.
    # The first line names the cause and the call, not the judge's guess of a crash.
    limit=(--time-limit 1)
    checks=(--score-max 0 --contains "your code's process: CPU time limit hit (1 s") ;;
  fork_bomb)
    solution1
    append1 <<'CPP'
#include <unistd.h>
namespace { struct Bomb { Bomb() { for (;;) fork(); } } bomb; }
CPP
    # Each process is under RLIMIT_CPU, and a dying one is replaced: the run's CPU budget, which
    # counts all its processes, is what ends it (not the wall clock). One second, as above.
    limit=(--time-limit 1)
    checks=(--score-max 0 --contains "CPU time limit hit (1 s, all its processes)") ;;
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
    checks=(--full-marks --max-score @points --not-contains "FAKE") ;;
  edit_tests)  # edits tests and CMake files, plants a symlink and an odd name, submits stubs
    mkdir -p "$sub/$s1/tests"
    stub "$src/$s1/camera_rays.cpp" > "$sub/$s1/camera_rays.cpp"
    printf '#include <gtest/gtest.h>\nTEST(Perspective, CenterLooksAlongViewDirection) {}\n' \
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
    checks=(--full-marks --max-score @points --not-contains "HIDDEN READABLE") ;;
  include_hidden)  # tries to compile the hidden tests into its own code
    solution2; stages=2; limit=()
    echo '#include "hidden/hidden_test.cpp"' | append2
    checks=(--score-max 0 --contains "was not used" --contains "is not allowed") ;;
  # Calibration (the flag builds are calibrate_flags.sh): known bugs must fail.
  early_constructor)  # runs before the trusted test main to take the nonce: refused at build
    stub "$src/$s1/camera_rays.cpp" > "$sub/$s1/camera_rays.cpp"
    append1 <<'CPP'
#include <cstdlib>
#include <unistd.h>
__attribute__((constructor(101))) static void grab_nonce() {
  if (const char* fd = std::getenv("RT_GRADE_NONCE_FD")) { char b[32]; (void)!read(std::atoi(fd), b, 32); }
}
CPP
    checks=(--score-max 0 --contains "Build (compiling your files)" --contains "section .init_array.") ;;
  libc_override)  # its own write(): made local to its object, so GoogleTest's output and the
    # trusted records are untouched (before localization it would have replaced libc's for all)
    stub "$src/$s1/camera_rays.cpp" > "$sub/$s1/camera_rays.cpp"
    append1 <<'CPP'
#include <sys/syscall.h>
#include <unistd.h>
extern "C" ssize_t write(int, const void*, size_t size) { return ssize_t(size); }  // swallows all
CPP
    checks=(--score-max 0 --contains "not implemented" --not-contains "Build (compiling your files)") ;;
  calib_missing_specular)  # Blinn-Phong without its specular term
    mkdir -p "$sub/$s3"
    grep -v 'reflected += material.specular' "$src/$s3/blinn_phong.cpp" > "$sub/$s3/blinn_phong.cpp"
    cmp -s "$src/$s3/blinn_phong.cpp" "$sub/$s3/blinn_phong.cpp" && { echo "no specular term to remove"; exit 1; }
    stages=3; limit=()
    checks=(--test-failed "image specular_only" --test-failed "image direct_light"
            --test-passed "image diffuse_only" --test-passed "image ambient_only") ;;
  calib_acne)  # shadow rays start exactly at the hit point, without the offset
    mkdir -p "$sub/$s4"
    sed -e 's/offset_ray_origin(\([a-z_]*\)\.point, [^;]*);/\1.point;/' \
        -e 's/spawn_ray(\([a-z_]*\), [^,]*, \([^;]*\));/Ray{\1.point, \2, \1.time};/' \
        "$src/$s4/shadows.cpp" > "$sub/$s4/shadows.cpp"
    cmp -s "$src/$s4/shadows.cpp" "$sub/$s4/shadows.cpp" && { echo "no offset to remove"; exit 1; }
    stages=4; limit=()
    # The Cornell box (axis-aligned walls near the origin) happens to show no acne without the
    # offset; the other three scenes and every Acne.* unit test do.
    checks=(--test-failed "image shadows" --test-failed "image glass_shadows"
            --test-failed "image far_from_origin" --test-failed "Acne.") ;;
  calib_half_pixel)  # samples pixel corners instead of centres
    sed 's|Vec2 pixel, ImageSize size) {|Vec2 pixel, ImageSize size) {\n    pixel -= Vec2(0.5);|' \
      "$src/$s1/camera_rays.cpp" > "$sub/$s1/camera_rays.cpp"
    # The direction images are smooth gradients: half a pixel moves them by at most 2 levels,
    # within the tolerance, so the unit tests are what catches this bug (docs/grading.md).
    checks=(--test-failed "Perspective.PixelCentersAreSymmetric" --score-max 12) ;;
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

grade_and_check
