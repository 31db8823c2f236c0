#!/usr/bin/env bash
# The debug preset's sanitizers (address, undefined behaviour) on the subset every CI run can
# afford: the GL contexts and stage 09 on the GPU (a few Stage09 tests: EGL and OSMesa, compute
# shaders, the BVH, textures, the Shadertoy export) and OpenImageIO's texture system
# (Framework.OiioTextures.*), the code that talks to C libraries. The whole debug preset (`ctest --preset debug`) is the developer's; this is its CI
# slice. Everything is in CMakePresets.json's `sanitize-subset` presets (build/sanitized), which
# inherit the debug preset's flags and suppressions.
#   check_sanitized_subset.sh SOURCE_DIR
set -uo pipefail
cd "$1" || exit 1
log=build/sanitized.log
mkdir -p build && : > "$log"
start=$(date +%s)
cmake --preset sanitize-subset >> "$log" 2>&1 || { tail -30 "$log"; echo "FAIL: configure (log: $log)"; exit 1; }
cmake --build --preset sanitize-subset >> "$log" 2>&1 ||
  { tail -40 "$log"; echo "FAIL: the sanitized build (log: $log)"; exit 1; }
echo "sanitized subset built in $(( $(date +%s) - start )) s"
ctest --preset sanitize-subset
