#!/usr/bin/env bash
# One case of `rt-grade package` (grader/package/): each builds a package as an instructor would,
# reads it back and runs it the way its platform does, in a folder standing in for the platform's
# layout (the rehearsals, tools/*_rehearsal.sh, run them in a bare Debian root under the limits).
#   package.sh BIN_DIR SRC_DIR CASE
set -uo pipefail
bin=$1 src=$2 case=$3
source "$(dirname "$0")/case_lib.sh"

fail() { echo "FAIL: $*"; exit 1; }
starter1() { stub "$src/$s1/camera_rays.cpp" > "$1/camera_rays.cpp"; }
max1=$(stage_points 1)
# only_grading LISTING: a package's file list holds nothing an instructor's tree has beyond
# grading: no node modules, tools, docs, build tree, hidden tests, viewer (ImGui, GLFW and the X
# libraries they pull in).
only_grading() {
  for pattern in node_modules '/tools/' '/docs/' 'CMakeCache.txt' '\.ninja' '/\.git/' \
                 '/hidden/' 'install-deps.sh' '\.devcontainer' 'glfw' 'imgui' 'libX11'; do
    if grep -qE "$pattern" "$1"; then fail "the package holds $pattern: $(grep -E "$pattern" "$1" | head -n 2)"; fi
  done
}

case $case in
  gradescope)  # the zip's content and settings, run_autograder with the rate limit, the audit
    "$bin/rt-grade" package --source "$src" --stages 1 --max-per-day 3 --out "$work/ag.zip" > "$work/log" 2>&1 ||
      { cat "$work/log"; fail "package"; }
    unzip -l "$work/ag.zip" > "$work/list" || fail "unzip -l"
    for f in setup.sh run_autograder rt-grade/bin/rt-grade rt-grade/packages.txt rt-grade/settings.sh \
             rt-grade/cache/private/plan.json; do
      grep -q " $f\$" "$work/list" || fail "$f missing from the zip"
    done
    only_grading "$work/list"
    root=$work/autograder
    mkdir -p "$root/source" "$root/submission"
    (cd "$root/source" && unzip -q "$work/ag.zip") || fail "unzip"
    cp "$root/source/run_autograder" "$root/"
    grep -qx "stages='1'  # --stages; empty: every stage" "$root/source/rt-grade/settings.sh" || fail "--stages not in settings.sh"
    grep -q "^max_per_day=3 " "$root/source/rt-grade/settings.sh" || fail "--max-per-day not in settings.sh"
    # setup.sh installs the package list and nothing else by name; the audit held the list.
    bash -n "$root/source/setup.sh" || fail "setup.sh does not parse"
    grep -q 'packages.txt' "$root/source/setup.sh" || fail "setup.sh does not install packages.txt"
    if grep -qE 'install-deps|cmake|npm|chromium' "$root/source/setup.sh"; then fail "setup.sh builds or installs the tree's tools"; fi
    cp "$src/$s1/camera_rays.cpp" "$root/submission/"
    now=$(date -u +%FT%T.000000+00:00) hour_ago=$(date -u -d '-1 hour' +%FT%T.000000+00:00)
    printf '{"created_at": "%s", "users": [{"email": "s@x", "id": 1, "name": "S"}], "previous_submissions": []}\n' \
      "$now" > "$root/submission_metadata.json"
    RT_AUTOGRADER_ROOT=$root "$root/run_autograder" > "$work/run.log" 2>&1 || { cat "$work/run.log"; fail "run_autograder"; }
    "$bin/results_check" "$root/results/results.json" --full-marks --full-marks-tag stage01 || fail "reference not full marks"
    [ "$(jq '.score' "$root/results/results.json")" = "$max1" ] || fail "score is not stage 01's $max1 points"
    # Three graded submissions in the last hour (this one's results): the fourth is refused, with
    # a valid results.json that says so.
    jq --arg now "$now" --arg t "$hour_ago" \
      '{created_at: $now, users: [{email: "s@x", id: 1, name: "S"}],
        previous_submissions: [range(3) as $i | {submission_time: $t, score: .score, results: .}]}' \
      "$root/results/results.json" > "$work/metadata.json" && mv "$work/metadata.json" "$root/submission_metadata.json"
    RT_AUTOGRADER_ROOT=$root "$root/run_autograder" > "$work/run.log" 2>&1 || { cat "$work/run.log"; fail "run_autograder (refused)"; }
    "$bin/results_check" "$root/results/results.json" --contains "This submission was not graded" > /dev/null ||
      { jq . "$root/results/results.json" | head -20; fail "the fourth submission in a day was graded"; }
    printf '{"created_at": "%s", "previous_submissions": []}\n' "$now" > "$root/submission_metadata.json"
    # Gradescope's timeout near: rt-grade stopped at the deadline still leaves valid results. The
    # submission waits 3 s in every test process, so the grading outlasts its 1 s deadline however
    # fast the machine (stage 01 alone can grade within a second).
    cat >> "$root/submission/camera_rays.cpp" << 'EOF_SLOW'
#include <chrono>
#include <thread>
namespace {
[[maybe_unused]] const bool kSlowOnPurpose = [] {
    std::this_thread::sleep_for(std::chrono::seconds(3));
    return true;
}();
}  // namespace
EOF_SLOW
    sed -i 's/^deadline_seconds=[0-9]*/deadline_seconds=1/' "$root/source/rt-grade/settings.sh"
    RT_AUTOGRADER_ROOT=$root "$root/run_autograder" > "$work/run.log" 2>&1
    "$bin/results_check" "$root/results/results.json" --contains "Grading was interrupted" > /dev/null ||
      fail "a grading stopped at the deadline did not write its results"
    sed -i 's/^deadline_seconds=1/deadline_seconds=540/' "$root/source/rt-grade/settings.sh"
    starter1 "$root/submission"
    RT_AUTOGRADER_ROOT=$root "$root/run_autograder" > "$work/run.log" 2>&1 || fail "run_autograder (starter)"
    [ "$(jq '.score' "$root/results/results.json")" = 0 ] || fail "the starter stub scores points"
    # The audit passes the package as built (package ran it too), and fails it once Debian-12-only
    # pieces are added: the check can fail.
    grep -q "audit: .* 0 findings" "$work/log" || fail "package did not run the audit"
    cp -a "$root/source/rt-grade" "$work/bundle" && bundle=$work/bundle list=$src/grader/package/target_packages.txt
    bash "$src/grader/package/audit_bundle.sh" "$bundle" "$list" || fail "the audit fails the package as built"
    # 1. a program that needs GLIBC_2.36 (arc4random: Debian 12 has it, Ubuntu 22.04 does not);
    printf '#include <stdlib.h>\nint main(void) { return (int)(arc4random() & 1); }\n' > "$work/new.c"
    gcc -o "$bundle/bin/needs-new-glibc" "$work/new.c" || fail "gcc"
    # 2. a program linked to a library that is neither shipped nor on the target list;
    printf 'int debian_only(void) { return 1; }\n' > "$work/lib.c"
    gcc -shared -fPIC -Wl,-soname,libdebianonly.so.1 -o "$work/libdebianonly.so.1" "$work/lib.c" || fail "gcc"
    printf 'int debian_only(void);\nint main(void) { return debian_only(); }\n' > "$work/main.c"
    gcc -o "$bundle/bin/needs-unshipped" "$work/main.c" "$work/libdebianonly.so.1" || fail "gcc"
    # 3. an object linked on the target that calls a C library function newer than 2.35;
    printf '#include <stdlib.h>\nunsigned draw(void) { return arc4random(); }\n' > "$work/obj.c"
    gcc -c -o "$bundle/cache/workspace/src/build/new.o" "$work/obj.c" || fail "gcc"
    # 4. a package name that is not on the list.
    echo chromium >> "$bundle/packages.txt"
    bash "$src/grader/package/audit_bundle.sh" "$bundle" "$list" > "$work/audit.log" && { cat "$work/audit.log"; fail "the broken bundle passes"; }
    cat "$work/audit.log"
    for expected in "bin/needs-new-glibc needs GLIBC_2.36" "bin/needs-unshipped needs libdebianonly.so.1" \
                    "build/new.o calls arc4random" "asks for chromium"; do
      grep -q "$expected" "$work/audit.log" || fail "the audit does not report: $expected"
    done
    exit 0 ;;
  prairielearn)  # the image context, and its entry point under PrairieLearn's contract
    out=$work/pl
    "$bin/rt-grade" package --source "$src" --platform prairielearn --stages 1 --out "$out" > "$work/log" 2>&1 ||
      { cat "$work/log"; fail "package"; }
    for f in Dockerfile entrypoint.sh rt-grade/bin/rt-grade rt-grade/packages.txt; do
      [ -e "$out/$f" ] || fail "$f missing from the image context"
    done
    (cd "$out" && find . -type f) > "$work/list" && only_grading "$work/list"
    grep -q '^FROM debian:12' "$out/Dockerfile" || fail "the Dockerfile is not from Debian 12"
    grep -q '^ENTRYPOINT \["/grader/entrypoint.sh"\]' "$out/Dockerfile" || fail "no entry point"
    # validate ROOT: results.json holds PrairieLearn's fields and is at most 1 MiB.
    validate() {
      local r=$1/results/results.json
      [ -s "$r" ] || fail "no results.json"
      [ "$(stat -c %s "$r")" -le 1048576 ] || fail "results.json over 1 MiB"
      jq -e '(.gradable | type == "boolean") and (.score | type == "number") and .score >= 0 and .score <= 1
             and (.tests | type == "array")
             and all(.tests[]; (.name | type == "string") and (.points | type == "number")
                     and (.max_points | type == "number") and (.message | type == "string")
                     and (.output | type == "string"))
             and all((.images // [])[]; .url | startswith("data:image/png;base64,"))' "$r" > /dev/null ||
        { head -c 2000 "$r"; fail "results.json misses PrairieLearn's fields"; }
    }
    # run WHAT: /grade laid out as PrairieLearn mounts it, the entry point run; it must exit 0.
    run() {
      rm -rf "$work/grade" && mkdir -p "$work/grade/student" "$work/grade/data" "$work/grade/results"
      case $1 in
        reference) cp "$src/$s1/camera_rays.cpp" "$work/grade/student/" ;;
        starter) starter1 "$work/grade/student" ;;
        stage2) cp "$src/$s2/intersections.cpp" "$work/grade/student/"
                echo '{"params": {"rt_stages": "2"}}' > "$work/grade/data/data.json" ;;
      esac
      RT_PL_ROOT=$work/grade RT_BUNDLE=${2:-$out/rt-grade} bash "$out/entrypoint.sh" || fail "the entry point exited non-zero ($1)"
      validate "$work/grade"
    }
    r=$work/grade/results/results.json
    run reference
    jq -e '.gradable == true and .score == 1' "$r" > /dev/null || { jq '.score, .message' "$r"; fail "reference: not gradable with score 1"; }
    run starter
    jq -e '.gradable == true and .score == 0 and any(.tests[]; .points < .max_points)' "$r" > /dev/null || fail "starter: not score 0"
    run empty
    jq -e '.gradable == false and (.message | length > 0)' "$r" > /dev/null || fail "an empty submission is gradable"
    run stage2  # data.json's params.rt_stages picks stage 02
    jq -e '.gradable == true and .score == 1 and all(.tests[]; .name | startswith("Stage 02"))' "$r" > /dev/null ||
      fail "params.rt_stages did not grade stage 02"
    # The grader itself broken, mid-run (an unreadable plan) or before it starts (no program):
    # still exit 0, with gradable false.
    cp -a "$out/rt-grade" "$work/broken" && echo '{' > "$work/broken/cache/private/plan.json"
    run reference "$work/broken"
    jq -e '.gradable == false' "$r" > /dev/null || fail "a grader that stopped mid-run scored the student"
    rm "$work/broken/bin/rt-grade"
    run reference "$work/broken"
    jq -e '.gradable == false' "$r" > /dev/null || fail "a grader that did not start scored the student"
    exit 0 ;;
  autolab)  # make in Tango's layout: the last line is the score, also after a forced timeout
    out=$work/al
    "$bin/rt-grade" package --source "$src" --platform autolab --stages 1 --problem-names 1=camera --out "$out" > "$work/log" 2>&1 ||
      { cat "$work/log"; fail "package"; }
    [ -f "$out/autograde-Makefile" ] && [ -f "$out/autograde.tar" ] || fail "autograde-Makefile or autograde.tar missing"
    tar -tf "$out/autograde.tar" > "$work/list" && only_grading "$work/list"
    # job NAME: a folder as Tango lays it out (the Makefile, the tar, the hand-in).
    job() {
      rm -rf "$work/$1" && mkdir -p "$work/$1"
      cp "$out/autograde-Makefile" "$work/$1/Makefile" && cp "$out/autograde.tar" "$work/$1/"
    }
    job full
    cp "$src/$s1/camera_rays.cpp" "$work/full/camera_rays.cpp"
    (cd "$work/full" && make -s > ../full.out 2> ../full.err) || fail "make"
    tail -n 1 "$work/full.out" | jq -e --argjson max "$max1" '.scores.camera == $max and .scoreboard[0] == $max' > /dev/null ||
      { tail -n 3 "$work/full.out"; fail "the last line is not full marks for problem camera"; }
    # Student output and the grader's log stay off stdout: every line is a score line.
    if grep -vq '^{"scoreboard":\|^{"scores":' "$work/full.out"; then head -n 5 "$work/full.out"; fail "stdout holds more than score lines"; fi
    [ "$(wc -l < "$work/full.out")" -gt 2 ] || fail "no running total between the first and last line"
    # A timeout mid-run (Autolab kills the job): the last line must still be a score.
    job killed
    cp "$src/$s1/camera_rays.cpp" "$work/killed/"
    (cd "$work/killed" && exec setsid make -s > ../killed.out 2> /dev/null) &
    maker=$!
    for _ in $(seq 600); do [ "$(wc -l < "$work/killed.out" 2> /dev/null || echo 0)" -ge 3 ] && break; sleep 0.1; done
    kill -KILL -- -"$maker" 2> /dev/null
    wait "$maker" 2> /dev/null
    lines=$(wc -l < "$work/killed.out")
    [ "$lines" -ge 3 ] && [ "$lines" -lt "$(wc -l < "$work/full.out")" ] || fail "the kill did not land mid-run ($lines lines)"
    tail -n 1 "$work/killed.out" | jq -e '.scores.camera | type == "number"' > /dev/null ||
      { tail -n 2 "$work/killed.out"; fail "after a kill the last line is not a score"; }
    # A tar hand-in is unpacked; the starter stub scores 0.
    job tarred
    starter1 "$work" && tar -C "$work" -cf "$work/tarred/handin.tar" camera_rays.cpp
    (cd "$work/tarred" && make -s > ../tarred.out 2> /dev/null) || fail "make (tar)"
    tail -n 1 "$work/tarred.out" | jq -e '.scores.camera == 0' > /dev/null || fail "the starter in a tar scores points"
    exit 0 ;;
  option_errors)  # an option where it means nothing is refused in one line, before any work
    expect_error() {  # MESSAGE ARGS...: exit 2 (or 1) and MESSAGE on stderr
      local message=$1; shift
      "$bin/rt-grade" package --source "$src" --out "$work/x" "$@" > /dev/null 2> "$work/err" && fail "accepted: $*"
      grep -q "$message" "$work/err" || { cat "$work/err"; fail "no '$message' for: $*"; }
      [ "$(wc -l < "$work/err")" -le 2 ] || { cat "$work/err"; fail "more than a line for: $*"; }
    }
    expect_error "max-per-day is Gradescope's" --platform autolab --max-per-day 3
    expect_error "max-per-day is Gradescope's" --platform prairielearn --max-per-day 3
    expect_error "names Autolab's problems" --platform gradescope --problem-names 1=camera
    expect_error "expected STAGE=NAME" --platform autolab --problem-names camera
    expect_error "stage 42 has no grading.json" --stages 42
    expect_error "platform" --platform moodle
    [ ! -e "$work/x" ] || fail "a refused package wrote something"
    exit 0 ;;
esac
echo "unknown case $case"
exit 2
