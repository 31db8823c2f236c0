#!/usr/bin/env bash
# The reference renderer against POV-Ray 3.7 on the same Whitted scene (issue 27's yardstick):
# stage 05's whitted.json and tools/bench/povray/whitted.pov (the same 120 boxes, two spheres,
# light and camera), 1024x768, 2 threads, end to end (process start, parsing, rendering, PNG).
# Prints hyperfine's figures and the ratios (wall time, and user + system time), and keeps the
# three images in OUT_DIR to look at side by side. Asserts nothing: timings on a shared 2-core
# machine are figures, not tests.
#   tools/bench_povray.sh [BUILD_DIR] [OUT_DIR]      (defaults: build, /tmp/rt-bench-povray)
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$src/build}" && pwd)
out=${2:-/tmp/rt-bench-povray}
for tool in hyperfine povray jq; do
  command -v "$tool" > /dev/null || { echo "bench_povray: needs $tool (scripts/install-deps.sh)"; exit 1; }
done
mkdir -p "$out"
scene=$src/stages/05-recursion/scenes/whitted.json
pov=$src/tools/bench/povray/whitted.pov
size=(--width 1024 --height 768)
rt_cmd="$build/bin/rt render $scene ${size[*]} --threads 2 -q -o $out/rt.png"
rt_bvh_cmd="$build/bin/rt render $scene ${size[*]} --threads 2 --accelerator bvh -q -o $out/rt-bvh.png"
# -D no display, -GA no console streams, +WT2 two threads; no anti-aliasing (rt takes one sample).
pov_cmd="povray -D -GA +WT2 +W1024 +H768 +FN +I$pov +O$out/povray.png"

echo "== machine: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg); $(povray --version 2>&1 | grep -m1 -o 'POV-Ray [0-9.]*' || echo POV-Ray)"
hyperfine -N --warmup 1 --runs "${RUNS:-10}" --style basic --export-json "$out/times.json" \
  -n "rt" "$rt_cmd" -n "rt --accelerator bvh" "$rt_bvh_cmd" -n "povray +WT2" "$pov_cmd" 2>&1 |
  grep -E "^Benchmark|Time \(mean|User:" || true

echo "== ratios (POV-Ray's time / rt's: above 1, rt is faster)"
jq -r '
  (.results | map({key: .command, value: {wall: .mean, cpu: ((.user // 0) + (.system // 0))}}) | from_entries) as $r
  | ["rt", "rt --accelerator bvh"][] as $name
  | "\($name): wall \(($r["povray +WT2"].wall / $r[$name].wall) * 100 | round / 100)x, "
    + "CPU \(($r["povray +WT2"].cpu / $r[$name].cpu) * 100 | round / 100)x "
    + "(rt \($r[$name].wall * 1000 | round) ms wall, \($r[$name].cpu * 1000 | round) ms CPU; "
    + "POV-Ray \($r["povray +WT2"].wall * 1000 | round) ms wall, \($r["povray +WT2"].cpu * 1000 | round) ms CPU)"
' "$out/times.json"
echo "== images: $out/rt.png $out/rt-bvh.png $out/povray.png"
