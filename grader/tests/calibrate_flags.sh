#!/usr/bin/env bash
# Calibration of the image thresholds against code generation: builds the reference renderer
# (`rt`: framework + every stage's solution) with the students' files compiled with other
# compiler flags, renders every graded scene with it and requires full points from the grader's
# own comparison (`rt-grade compare`). A threshold too tight for an honest build fails here.
# Only the students' files get the flags (RT_STUDENT_CXX_FLAGS): the grader compiles the
# framework with its own flags whatever a submission does, so that is where honest builds differ.
#   calibrate_flags.sh BIN_DIR SRC_DIR BUILD_DIR NAME "FLAGS" [CCACHE_DIR]
# The tree is a copy of SRC_DIR in BUILD_DIR/NAME/src, built in src/build like the grader's
# workspace, so the framework's objects are hits in the outer build's compiler cache
# (cmake/compiler_cache.cmake) and only the students' files compile. Kept between runs.
set -uo pipefail
bin=$1 src=$2 root=$3/$4 name=$4 flags=$5 ccache_dir=${6:-}
copy=$root/src build=$root/src/build
mkdir -p "$copy" || { echo "FAIL: cannot create $copy"; exit 1; }
start=$(date +%s)
# The sources only: no build folders, no history. Cleared first, so a file removed upstream is
# gone here too and a rerun builds what the source tree holds now.
find "$copy" -mindepth 1 -maxdepth 1 ! -name build -exec rm -rf {} + ||
  { echo "FAIL: cannot clear $copy"; exit 1; }
tar -C "$src" --exclude=./build --exclude='./build-*' --exclude=./.git -cf - . | tar -C "$copy" -xf - ||
  { echo "FAIL: cannot copy $src to $copy"; exit 1; }
# No viewer: `rt` only renders here, and the viewer's compile was a tenth of the build's CPU.
args=(-S "$copy" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DRT_VIEWER=OFF
      "-DRT_STUDENT_CXX_FLAGS=$flags")
if [ -n "$ccache_dir" ]; then args+=(-DRT_CCACHE=ON "-DRT_CCACHE_DIR=$ccache_dir"); else args+=(-DRT_CCACHE=OFF); fi
cmake "${args[@]}" > "$root/configure.log" 2>&1 || { cat "$root/configure.log"; echo "FAIL: configure"; exit 1; }
cmake --build "$build" --target rt -j "${RT_CALIBRATION_JOBS:-2}" > "$root/build.log" 2>&1 ||
  { tail -40 "$root/build.log"; echo "FAIL: building rt with the students' files at $flags"; exit 1; }
built=$(date +%s)
# The flags really reached the students' files (an override in the tree would make this vacuous).
# (grep -c, not -q: -q stops reading early, the first grep dies of SIGPIPE, and pipefail fails.)
students=$(grep -- "$flags" "$build/compile_commands.json" | grep -c "stages/")
[ "$students" -gt 0 ] || { echo "FAIL: $flags not in the students' compile commands"; exit 1; }
echo "$name: rt built with the students' files at '$flags' in $(( built - start )) s"
"$bin/rt-grade" compare --source "$src" --renderer "$build/bin/rt" --threads 2 ${RT_CALIBRATION_STAGES:+--stages "$RT_CALIBRATION_STAGES"}
code=$?
echo "$name: renders and comparison in $(( $(date +%s) - built )) s"
exit $code
