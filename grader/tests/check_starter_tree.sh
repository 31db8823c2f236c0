#!/usr/bin/env bash
# End-to-end check of `rt-grade release` (CTest: Release.StarterTreeLadder; step 1 alone:
# Release.StarterTreeText).
#
#   check_starter_tree.sh BIN_DIR SRC_DIR [--text-only]
#
# 1. Releases SRC_DIR (every stage stubbed) into a temporary directory and checks the text:
#    no solution markers left, stubs un-commented, student function signatures intact.
# 2. Configures (as the release preset does: Release, RT_WERROR=ON) and builds the starter tree's
#    stage tests (every stageNN*_tests target, the CGAL checks included, and `rt`, which some
#    stage-labelled tests run). Runs the starter README's two commands as a student would; the
#    second runs every test, and from its log every stage's tests must FAIL, pointing at the stub
#    ("not implemented") and at the handout ("README.md#").
# 3. For every stage N, re-releases into the same directory with --solved-through N --force
#    (only the student files change, so the build is incremental) and requires the tests of
#    stage N to PASS and those of stage N+1 to FAIL on their stubs (why that suffices: below).
# 4. With every stage solved, the README's test command passes: finishing fails no test.
#
# --text-only stops after step 1 (seconds; CTest: Release.StarterTreeText, in every CI run). The
# whole ladder is a rehearsal of a student's course (minutes; label rehearsal, outside CI's
# default run: `ctest --preset rehearsal`).
#
# Environment: RT_RELEASE_CONFIGURE_ARGS: extra arguments for the starter tree's cmake
# configure line; RT_CCACHE_DIR: the outer build's compiler cache, which the starter tree (laid
# out as SOURCE/build like the outer tree) and its grading workspace then share
# (cmake/compiler_cache.cmake): only the student files, stubbed here, compile afresh.
set -u -o pipefail

if [[ $# -lt 2 || $# -gt 3 || ( $# -eq 3 && "$3" != "--text-only" ) ]]; then
    echo "usage: $0 BIN_DIR SRC_DIR [--text-only]" >&2
    exit 2
fi
TEXT_ONLY="${3:-}"
RT_GRADE="$1/rt-grade"
SRC="$(cd "$2" && pwd)"
JOBS="$(nproc 2>/dev/null || echo 2)"

[[ -x "$RT_GRADE" ]] || { echo "FAIL: $RT_GRADE not built (cmake --build <dir> --target rt-grade)"; exit 1; }

TMP="$(mktemp -d "${TMPDIR:-/tmp}/rt-starter-check.XXXXXX")"
trap 'rm -rf "$TMP"' EXIT
STARTER="$TMP/starter"
BUILD="$STARTER/build"

fail() { echo "FAIL: $*"; exit 1; }
ok() { echo "ok:   $*"; }

# The working tree as it is now, new files included: a release from a clean checkout gets the
# tracked files only, which is the same set once everything is committed.
RELEASE_ARGS=()
if git -C "$SRC" rev-parse --is-inside-work-tree > /dev/null 2>&1; then
    RELEASE_ARGS+=(--include-untracked)
fi

# Stages: stages/NN-name/ folders with a stage.json. Their test targets are stageNN_tests.
STAGES=()
for json in "$SRC"/stages/[0-9][0-9]-*/stage.json; do
    [[ -f "$json" ]] || continue
    folder="$(basename "$(dirname "$json")")"
    STAGES+=("${folder:0:2}")
done
[[ ${#STAGES[@]} -gt 0 ]] || fail "no stages/NN-*/stage.json in $SRC"
LAST_STAGE="${STAGES[${#STAGES[@]}-1]}"
echo "stages: ${STAGES[*]}"
TARGETS=()  # chosen once the starter tree is configured

# Files of SRC holding solution regions (the student files), relative to SRC.
MARKER_LINE='^[[:space:]]*// (BEGIN SOLUTION|STUB|END SOLUTION)[[:space:]]*$'
mapfile -t STUDENT_FILES < <(cd "$SRC" && grep -rlE "$MARKER_LINE" stages | sort)
[[ ${#STUDENT_FILES[@]} -gt 0 ]] || fail "no solution markers under $SRC/stages: nothing to check"

start=$SECONDS

# --- 1. Release and check the text -------------------------------------------------------
"$RT_GRADE" release --source "$SRC" --out "$STARTER" "${RELEASE_ARGS[@]}" \
    || fail "rt-grade release exited with $?"
ok "released $SRC into $STARTER ${RELEASE_ARGS[*]}"

# Marker lines nowhere. The marker words nowhere either, except in the grader (which strips
# them) and in Markdown documentation that names them (listed, for a human to glance at).
if grep -rnE --exclude-dir=build "$MARKER_LINE" "$STARTER"; then
    fail "marker lines left in the starter tree (above)"
fi
if grep -rn --exclude-dir=build --exclude='*.md' "BEGIN SOLUTION" "$STARTER" | grep -v "^$STARTER/grader/"; then
    fail "'BEGIN SOLUTION' left in the starter tree (above)"
fi
mentions="$(grep -rl --exclude-dir=build --include='*.md' "BEGIN SOLUTION" "$STARTER" | sed "s|^$STARTER/||" | tr '\n' ' ')"
ok "no marker lines anywhere; no 'BEGIN SOLUTION' outside grader/ and Markdown docs (named in: ${mentions:-none})"

signatures=0
for file in "${STUDENT_FILES[@]}"; do
    released="$STARTER/$file"
    [[ -f "$released" ]] || fail "$file missing from the starter tree"
    # Function definitions start at column 0: "<type> name(" (continuation lines included);
    # helpers inside a solution region (stripped with it) are the solution's, not the student's.
    while IFS= read -r line; do
        grep -Fxq -- "$line" "$released" || fail "$file: signature line lost: $line"
        signatures=$((signatures + 1))
    done < <(awk '/^[ \t]*\/\/ BEGIN SOLUTION[ \t]*$/ {s=1} !s {print} /^[ \t]*\/\/ END SOLUTION[ \t]*$/ {s=0}' "$SRC/$file" \
                 | grep -E '^[A-Za-z_][A-Za-z0-9_:<>,&* ]*[ &*][A-Za-z_][A-Za-z0-9_]*\(' \
                 | grep -vE '^(namespace|using|return|if|for|while|struct|class|enum)\b')
    # Regions whose stub is code (not a region of helper functions, whose stub is a comment).
    regions="$(awk '/^[ \t]*\/\/ BEGIN SOLUTION[ \t]*$/ {s=1; code=0; next}
                    /^[ \t]*\/\/ STUB[ \t]*$/ {s=2; next}
                    /^[ \t]*\/\/ END SOLUTION[ \t]*$/ {if (code) n++; s=0; next}
                    s==2 && !/^[ \t]*\/\/ ?\/\// {code=1}
                    END {print n+0}' "$SRC/$file")"
    # C++ stubs name the section in a string; GLSL ones in a comment (GLSL has no strings).
    stubs="$(grep -cE '^[[:space:]]*RT_NOT_IMPLEMENTED\(("|\); +// ).*README\.md#' "$released")"
    [[ "$stubs" -ge "$regions" ]] \
        || fail "$file: $regions solution regions with a code stub but only $stubs un-commented RT_NOT_IMPLEMENTED stubs"
done
[[ $signatures -gt 0 ]] || fail "found no function signatures in the student files"
ok "${#STUDENT_FILES[@]} student files: $signatures signature lines kept, every region has an RT_NOT_IMPLEMENTED stub"
if [[ -n "$TEXT_ONLY" ]]; then
    # The starter tree configures as a grading workspace configures its copy (`rt-grade .`):
    # an instructor's build without viewer or window, with what the release left out missing.
    cmake -S "$STARTER" -B "$TMP/workspace-configure" -G Ninja -DCMAKE_BUILD_TYPE=Release \
        -DRT_INSTRUCTOR=ON -DRT_VIEWER=OFF -DRT_GL_WINDOW=OFF -DRT_CCACHE=OFF > "$TMP/configure.log" 2>&1 \
        || { tail -20 "$TMP/configure.log"; fail "the starter tree does not configure as rt-grade . configures it"; }
    ok "the starter tree configures as a grading workspace does (RT_INSTRUCTOR=ON)"
    echo "total $((SECONDS - start)) s (--text-only: the build and the ladder are Release.StarterTreeLadder's)"
    exit 0
fi

# --- 2. Build the starter tree; its stage tests must fail on the stubs --------------------
build_stage_tests() {
    # shellcheck disable=SC2086 # extra arguments are meant to be word-split
    local cache=()
    [[ -n "${RT_CCACHE_DIR:-}" ]] && cache=("-DRT_CCACHE_DIR=$RT_CCACHE_DIR")
    cmake -S "$STARTER" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release -DRT_WERROR=ON "${cache[@]}" ${RT_RELEASE_CONFIGURE_ARGS:-} \
        > "$TMP/configure.log" 2>&1 \
        || { tail -n 40 "$TMP/configure.log"; fail "configuring the starter tree failed"; }
    # Every stage test executable (stageNN_tests, stageNN_<what>_tests such as the CGAL checks),
    # and `rt`: some tests labelled stageNN run the renderer (Render.ThreadCountIsBitIdentical).
    if [[ ${#TARGETS[@]} -eq 0 ]]; then
        local all
        all="$(cmake --build "$BUILD" --target help 2>/dev/null | sed -n 's/^\([A-Za-z0-9_]*\): .*/\1/p')"
        for n in "${STAGES[@]}"; do
            grep -qx "stage${n}_tests" <<< "$all" || fail "the starter tree has no target stage${n}_tests"
        done
        mapfile -t TARGETS < <(grep -E '^stage[0-9][0-9](_[A-Za-z0-9]+)*_tests$' <<< "$all" | sort)
        grep -qx rt <<< "$all" && TARGETS+=(rt)
    fi
    # With stage numbers as arguments, only their test targets (and rt) are brought up to date.
    local wanted=("${TARGETS[@]}")
    if [[ $# -gt 0 ]]; then
        wanted=()
        for t in "${TARGETS[@]}"; do
            for n in "$@"; do [[ $t == rt || $t == stage${n}_* ]] && { wanted+=("$t"); break; }; done
        done
    fi
    cmake --build "$BUILD" --target "${wanted[@]}" > "$TMP/build.log" 2>&1 \
        || { grep -E "error|FAILED" "$TMP/build.log" | head -n 40; fail "building ${wanted[*]} failed"; }
}

# A stage with no tests would "pass" or "fail" for the wrong reason: say so plainly.
no_tests() {
    if grep -q "No tests were found" "$2"; then
        grep -q "BUILD_TESTING:BOOL=OFF" "$BUILD/CMakeCache.txt" 2>/dev/null \
            && echo "note: BUILD_TESTING is OFF in the starter build (a package config may set it before include(CTest))"
        fail "ctest -L stage$1 found no tests in the starter build"
    fi
}

build_stage_tests
ok "starter tree configured and built ${TARGETS[*]} ($((SECONDS - start)) s so far)"

# The part of a ctest log that belongs to the tests named PREFIX*: each one's status line and the
# output printed after it (ctest keeps a test's output together, also with -j).
tests_named() {
    awk -v p="$1" '/^ *[0-9]+\/[0-9]+ Test +#[0-9]+: / { keep = index($4, p) == 1 } keep' "$2"
}

# Every stage's tests fail on the stubs, each saying why. Read from the log of README command 2
# (below), which runs them all: a stage's tests are named StageNN.* (its label stageNN).
check_stubbed_stages() {
    for n in "${STAGES[@]}"; do
        log="$TMP/stage$n.stubbed.log"
        tests_named "Stage$n." "$1" > "$log"
        failed=$(grep -cE "^ *[0-9]+/[0-9]+ Test +#[0-9]+: " "$log")
        [[ $failed -gt 0 ]] || fail "README command 2 ran no Stage$n.* test in the starter tree"
        # Not one stage test may pass on stubs: a test that passes without the student's code tests
        # nothing the student wrote.
        if grep -E "^ *[0-9]+/[0-9]+ Test +#[0-9]+: .* Passed" "$log"; then
            fail "stage$n: the tests above pass in the starter tree although every function is a stub"
        fi
        grep -qi "not implemented" "$log" || { tail -n 30 "$log"; fail "stage$n: output never says 'not implemented'"; }
        # No stub may crash, and every failing test must say why: each test's output (from its
        # status line to the next one) names "not implemented".
        if grep -E "^ *[0-9]+/[0-9]+ Test +#[0-9]+: .*\*\*\*Exception" "$log"; then
            fail "stage$n: the tests above crash on the stubs instead of failing with 'not implemented'"
        fi
        silent="$(awk '/^ *[0-9]+\/[0-9]+ Test +#[0-9]+: / { if (name != "" && !said) print name; name = $4; said = 0; next }
                       /not implemented/ { said = 1 }
                       END { if (name != "" && !said) print name }' "$log")"
        [[ -z "$silent" ]] || fail "stage$n: these stubbed tests fail without saying 'not implemented': $silent"
        grep -q "README.md#" "$log" || { tail -n 30 "$log"; fail "stage$n: output never points at a handout section (README.md#)"; }
        ok "stage$n tests fail on the stubs ($failed tests), saying 'not implemented' and pointing at README.md#"
    done
}

# --- 2b. The student README, command by command, in the released tree ---------------------
# Its two commands (first image; the tests), then the stage loop for stage 01.
readme_start=$SECONDS
mapfile -t COMMANDS < <(awk '/^```sh$/ {inside=1; next} /^```$/ {inside=0} inside' "$STARTER/README.md" | head -n 2)
[[ ${#COMMANDS[@]} -eq 2 ]] || fail "the starter README does not open with two commands"
grep -q "rt-grade release\|rt-grade batch\|rt-grade package\|accuracy" "$STARTER/README.md" \
    && fail "the starter README names instructor commands"
(cd "$STARTER" && bash -c "${COMMANDS[0]}") > "$TMP/readme1.log" 2>&1 \
    || { tail -n 30 "$TMP/readme1.log"; fail "the starter README's first command failed"; }
[[ -s "$STARTER/gallery/01-camera-rays/perspective_directions.png" ]] || fail "the first command rendered no gallery"
ok "README command 1 (first image) in $((SECONDS - readme_start)) s"
readme2_start=$SECONDS
(cd "$STARTER" && bash -c "${COMMANDS[1]}") > "$TMP/readme2.log" 2>&1
rc=$?
[[ $rc -ne 0 ]] || fail "the starter README's test command passes although every stage is a stub"
grep -E "^ *[0-9]+/[0-9]+ Test +#[0-9]+: (Grader|Release|Calibration|Bench|Accuracy)\." "$TMP/readme2.log" \
    && fail "the starter README's test command runs instructor-only tests (above)"
if grep -E "^ *[0-9]+/[0-9]+ Test +#[0-9]+: (Framework|Render|Cli)\..*(Failed|Exception)" "$TMP/readme2.log"; then
    fail "framework tests fail in the starter tree (above)"
fi
ok "README command 2 (tests) in $((SECONDS - readme2_start)) s: only stage and framework tests, the stages fail on stubs"
check_stubbed_stages "$TMP/readme2.log"
(cd "$STARTER" && ctest --test-dir build -L stage01 --output-on-failure > "$TMP/loop-test.log" 2>&1)
grep -q "not implemented" "$TMP/loop-test.log" || fail "the loop's test command shows no failure message"
(cd "$STARTER" && build/bin/rt render stages/01-camera-rays/scenes/perspective_directions.json -o out.png -q) \
    || fail "the loop's render command failed"
(cd "$STARTER" && build/bin/rt-grade . > "$TMP/self-grade.log" 2>&1) || { cat "$TMP/self-grade.log"; fail "rt-grade . failed"; }
grep -q "Stage 01" "$TMP/self-grade.log" && ! grep -q "Stage 02" "$TMP/self-grade.log" \
    || { cat "$TMP/self-grade.log"; fail "rt-grade . in an untouched tree should grade stage 01 only"; }
grep -q "Report: .*report.html" "$TMP/self-grade.log" && [[ -s "$STARTER/report.html" ]] \
    || { cat "$TMP/self-grade.log"; fail "rt-grade . wrote or named no report"; }
ok "the stage loop: tests, render, rt-grade . (stage 01 only, report.html) ($((SECONDS - readme_start)) s for the README in all)"

# --- 3. The ladder: --solved-through N for every stage N ----------------------------------
# A student who could not finish stage N gets its solution (and those of earlier stages) with
# --solved-through N. Then the tests of stage N must pass with every later stage still a stub
# (no stage's tests may depend on a later stage's code), and those of stage N+1 must still
# fail on its stubs with every earlier stage solved (the solutions released do not make a later
# stage's stubs pass). Each rung runs those two labels and builds only their targets: stages
# before N passed on an earlier rung with more stubs around them, and the course tree's own CI
# runs every stage with everything solved. (A rung that ran every stage, one from the end, was
# dropped: it repeated those two checks and cost CI 17-30 s.)
# Same directory, --force: unchanged files keep their timestamps, so only the student files
# recompile against the existing build.
for solved in "${STAGES[@]}"; do
    pass_start=$SECONDS
    "$RT_GRADE" release --source "$SRC" --out "$STARTER" --solved-through "$((10#$solved))" --force \
        "${RELEASE_ARGS[@]}" > /dev/null || fail "rt-grade release --solved-through $((10#$solved)) exited with $?"
    rung=()
    for n in "${STAGES[@]}"; do
        ((10#$n == 10#$solved || 10#$n == 10#$solved + 1)) && rung+=("$n")
    done
    build_stage_tests "${rung[@]}"
    for n in "${rung[@]}"; do
        log="$TMP/stage$n.solved$solved.log"
        ctest --test-dir "$BUILD" -L "stage$n" --output-on-failure --no-tests=error -j "$JOBS" > "$log" 2>&1
        rc=$?
        no_tests "$n" "$log"
        if ((10#$n <= 10#$solved)); then
            [[ $rc -eq 0 ]] || { tail -n 60 "$log"; fail "--solved-through $((10#$solved)): stage$n tests fail with their solution released"; }
        else
            [[ $rc -ne 0 ]] && grep -qi "not implemented" "$log" \
                || { tail -n 30 "$log"; fail "--solved-through $((10#$solved)): stage$n tests do not fail on its stubs"; }
            if grep -E "^ *[0-9]+/[0-9]+ Test +#[0-9]+: .* Passed" "$log"; then
                fail "--solved-through $((10#$solved)): stage$n tests above pass although stage$n is stubbed"
            fi
        fi
    done
    next="the next fails on its stubs"
    [[ $solved == "$LAST_STAGE" ]] && next="no stage after it"
    ok "--solved-through $((10#$solved)): stages ${rung[0]}..$solved pass, $next ($((SECONDS - pass_start)) s)"
done

# --- 4. Finished: every stage written, C++ and GLSL, passes the README's test command ---------
# The last rung released every solution. A student who has finished must see no failure: no
# test may depend on a stub being there (a stub-report test skips once its stub is written).
finish_start=$SECONDS
(cd "$STARTER" && bash -c "${COMMANDS[1]}") > "$TMP/finished.log" 2>&1 ||
    { grep -E "^ *[0-9]+/[0-9]+ Test +#[0-9]+: .*(Failed|Exception|Timeout)" "$TMP/finished.log"
      tail -n 40 "$TMP/finished.log"; fail "the README's test command fails in a finished starter tree (above)"; }
ok "finished: README command 2 passes with every stage written ($((SECONDS - finish_start)) s)"
echo "total $((SECONDS - start)) s"
