#!/usr/bin/env bash
# Calibration of the image thresholds against code generation: builds the reference renderer
# (`rt`: framework + every stage's solution) in a build tree of its own with other compiler
# flags, renders every graded scene with it and requires full points from the grader's own
# comparison (`rt-grade compare`). A threshold too tight for an honest build fails here.
#   calibrate_flags.sh BIN_DIR SRC_DIR BUILD_DIR NAME "FLAGS" [LAUNCHER]
# BUILD_DIR/NAME is kept between runs, so a rerun only rebuilds what changed.
set -uo pipefail
bin=$1 src=$2 build=$3/$4 name=$4 flags=$5 launcher=${6:-}
mkdir -p "$3" || { echo "FAIL: cannot create $3"; exit 1; }
# No compiler cache: other flags, so nothing to share with the outer build. No viewer: `rt`
# only renders here, and the viewer's compile was a tenth of this build's CPU time.
args=(-S "$src" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DRT_WERROR=OFF -DRT_CCACHE=OFF -DRT_VIEWER=OFF
      "-DCMAKE_CXX_FLAGS_RELEASE=$flags -DNDEBUG" "-DCMAKE_C_FLAGS_RELEASE=$flags -DNDEBUG")
[ -n "$launcher" ] && args+=(-DCMAKE_CXX_COMPILER_LAUNCHER="$launcher")
start=$(date +%s)
cmake "${args[@]}" > "$build.configure.log" 2>&1 || { cat "$build.configure.log"; echo "FAIL: configure"; exit 1; }
cmake --build "$build" --target rt -j "${RT_CALIBRATION_JOBS:-2}" > "$build.build.log" 2>&1 ||
  { tail -40 "$build.build.log"; echo "FAIL: building rt with $flags"; exit 1; }
built=$(date +%s)
# The flags really reached the compiler (an override in the tree would make this test vacuous).
grep -q -- "$flags" "$build/compile_commands.json" || { echo "FAIL: $flags not in the compile commands"; exit 1; }
echo "$name: rt built with '$flags' in $(( built - start )) s"
"$bin/rt-grade" compare --source "$src" --renderer "$build/bin/rt" --threads 2 ${RT_CALIBRATION_STAGES:+--stages "$RT_CALIBRATION_STAGES"}
code=$?
echo "$name: renders and comparison in $(( $(date +%s) - built )) s"
exit $code
