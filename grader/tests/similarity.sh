#!/usr/bin/env bash
# `rt-grade similarity` on a synthetic cohort built from the instructor's own solutions
# (CTest: Grader.Similarity.cohort and Grader.Similarity.errors).
#
#   similarity.sh BIN_DIR SRC_DIR cohort|errors
#
# cohort: four submissions, each in another layout the grader's intake reads
#   ada/      the reference solutions of stages 01, 02 and 09's intersect.glsl (stage folders)
#   bob.zip   ada's stage 02 and intersect.glsl disguised: identifiers renamed, comments
#             dropped and others written, functions reordered (a whole tree, zipped)
#   cy/       an independent stage 02 (stages/02-intersections/hidden/similarity_independent.cpp:
#             geometric ray-sphere, Moller-Trumbore, other slabs and nearest-hit code; in hidden/
#             so that no starter tree ships it)
#   dee/      the starter files of every stage, untouched
# and requires: the two disguised copies ranked first and flagged; ada and cy (same stage,
# same starter code around different solutions) under the threshold; nothing about dee.
# errors: a missing DIR, an empty DIR and a missing similarity tester each give one line.
set -u -o pipefail
[[ $# -eq 3 ]] || { echo "usage: $0 BIN_DIR SRC_DIR cohort|errors" >&2; exit 2; }
rt_grade="$1/rt-grade" src=$(cd "$2" && pwd) case=$3
work=$(mktemp -d /tmp/rt-grade-sim-XXXXXX)
trap '[[ -n ${RT_SIM_KEEP:-} ]] || rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
ok() { echo "ok:   $*"; }
s2=stages/02-intersections s9=stages/09-gpu s1=stages/01-camera-rays

source "$(dirname "$0")/disguise.sh"  # disguise FILE: a copier's version of FILE

# What the cohort is made of: the solved and the starter trees, as `rt-grade release` writes them.
release_trees() {
  local args=()
  git -C "$src" rev-parse --is-inside-work-tree > /dev/null 2>&1 && args+=(--include-untracked)
  "$rt_grade" release --source "$src" --out "$work/solved" --solved-through 99 "${args[@]}" \
    > /dev/null || fail "rt-grade release --solved-through 99"
  "$rt_grade" release --source "$src" --out "$work/starter" "${args[@]}" > /dev/null ||
    fail "rt-grade release"
}

build_cohort() {
  local c=$work/cohort
  mkdir -p "$c/ada/02-intersections" "$c/ada/09-gpu" "$c/ada/01-camera-rays" \
           "$c/bob/$s2" "$c/bob/$s9" "$c/cy" "$c/dee"
  cp "$work/solved/$s2/intersections.cpp" "$c/ada/02-intersections/"
  cp "$work/solved/$s9/intersect.glsl" "$c/ada/09-gpu/"
  cp "$work/solved/$s1/camera_rays.cpp" "$c/ada/01-camera-rays/"
  disguise "$work/solved/$s2/intersections.cpp" > "$c/bob/$s2/intersections.cpp"
  disguise "$work/solved/$s9/intersect.glsl" > "$c/bob/$s9/intersect.glsl"
  (cd "$c" && zip -q -r bob.zip bob && rm -rf bob) || fail "zip bob"
  cp "$src/$s2/hidden/similarity_independent.cpp" "$c/cy/intersections.cpp"
  cp -r "$work/starter/stages" "$c/dee/"
  grep -q 'span' "$c/cy/intersections.cpp" && fail "cy's solution must not be a disguised copy"
}

# The score column of pairs.csv for FILE's pair of A and B (empty when they share nothing).
score() {
  awk -F, -v f="\"$1\"" -v a="\"$2\"" -v b="\"$3\"" '$1 == f && $2 == a && $3 == b { print $6 }' \
    "$work/sim/pairs.csv"
}

check_cohort() {
  local csv=$work/sim/pairs.csv html=$work/sim/index.html
  [[ -f $csv && -f $html ]] || fail "no pairs.csv or index.html in $work/sim"
  cat "$csv"
  local copy_cpp copy_glsl indep
  copy_cpp=$(score "$s2/intersections.cpp" ada bob)
  copy_glsl=$(score "$s9/intersect.glsl" ada bob)
  indep=$(score "$s2/intersections.cpp" ada cy)
  echo "scores: ada-bob intersections.cpp ${copy_cpp:-0}%, intersect.glsl ${copy_glsl:-0}%;" \
       "ada-cy intersections.cpp ${indep:-0}%"
  (( ${copy_cpp:-0} >= 90 && ${copy_glsl:-0} >= 90 )) || fail "a disguised copy scored under 90%"
  (( ${indep:-0} < 50 )) || fail "independent solutions scored ${indep}% (threshold 50%)"
  # Ranked first: the two copies head pairs.csv, which is sorted by score.
  sed -n 2,3p "$csv" | grep -c '"ada","bob"' | grep -qx 2 || fail "the copies are not ranked first"
  ! grep -q '"dee"' "$csv" || fail "the untouched starter files made a pair"
  grep -q '"bob","cy"' "$csv" && [[ $(score "$s2/intersections.cpp" bob cy) -ge 50 ]] &&
    fail "bob and cy flagged"
  # The page: two flagged pairs, their regions side by side, the code HTML-escaped.
  grep -q '2 at or above 50%' "$html" || fail "index.html does not flag exactly 2 pairs"
  grep -q 'id="pair-2"' "$html" && ! grep -q 'id="pair-3"' "$html" || fail "pair sections"
  grep -q '<h3>ada lines [0-9]*-[0-9]* &harr; bob lines' "$html" || fail "no side-by-side region"
  grep -q 'const Vec3&amp; d = ray.direction' "$html" || fail "code not shown escaped"
  ok "copies ${copy_cpp}% and ${copy_glsl}% flagged first; independent pair ${indep:-0}%"
}

# The one line of standard error a failed run must give, matched against PATTERN.
expect_error() {
  local pattern=$1; shift
  local err
  err=$("$@" 2>&1 > /dev/null) && fail "exit 0 for: $*"
  [[ $(printf '%s\n' "$err" | wc -l) -eq 1 ]] || fail "not one line: $err"
  grep -q -- "$pattern" <<< "$err" || fail "'$err' does not say '$pattern'"
  ok "$err"
}

case $case in
  cohort)
    release_trees
    build_cohort
    start=$EPOCHREALTIME
    "$rt_grade" similarity "$work/cohort" --out "$work/sim" --source "$src" ||
      fail "rt-grade similarity exited $?"
    awk -v a="$start" -v b="$EPOCHREALTIME" 'BEGIN { printf "rt-grade similarity: %.2f s\n", b - a }'
    check_cohort
    ;;
  errors)
    expect_error 'no such folder' "$rt_grade" similarity "$work/missing" --out "$work/sim"
    mkdir -p "$work/empty"
    expect_error '0 submission(s) found' "$rt_grade" similarity "$work/empty" --out "$work/sim"
    mkdir -p "$work/two/a" "$work/two/b" "$work/nopath"
    expect_error 'apt-get install similarity-tester' env PATH="$work/nopath" \
      "$rt_grade" similarity "$work/two" --out "$work/sim"
    ;;
  *) echo "unknown case $case" >&2; exit 2 ;;
esac
