#!/usr/bin/env bash
# The reference renderer against POV-Ray 3.7 (issue 27's yardstick), 1024x768, 2 threads, end to
# end (process start, parsing, rendering, PNG), on two scenes written in both formats:
#   plane  - issue 27's Whitted scene: a plane, a mirror and a glass sphere, one point light,
#            depth 5 (tools/bench/scenes/whitted_plane.json, tools/bench/povray/whitted_plane.pov)
#   boxes  - stage 05's whitted.json, its floor made of 120 boxes (tools/bench/povray/whitted.pov);
#            rt traces it with its BVH (--accelerator bvh), as POV-Ray bounds its objects.
# Prints hyperfine's figures and the ratios (wall time, and user + system time), and keeps the
# images in OUT_DIR to look at side by side. Asserts nothing: timings on a shared 2-core machine
# are figures, not tests.
#   tools/bench_povray.sh [BUILD_DIR] [OUT_DIR]      (defaults: build, /tmp/rt-bench-povray)
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$src/build}" && pwd)
out=${2:-/tmp/rt-bench-povray}
for tool in hyperfine povray jq; do
  command -v "$tool" > /dev/null || { echo "bench_povray: needs $tool (scripts/install-deps.sh)"; exit 1; }
done
mkdir -p "$out"
size=(--width 1024 --height 768)
rt() { echo "$build/bin/rt render $1 ${size[*]} --threads 2 -q -o $out/$2.png ${3:-}"; }
# -D no display, -GA no console streams, +WT2 two threads; no anti-aliasing (rt takes one sample).
pov() { echo "povray -D -GA +WT2 +W1024 +H768 +FN +I$src/tools/bench/povray/$1.pov +O$out/$2.png"; }

echo "== machine: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg); $(povray --version 2>&1 | grep -m1 -o 'POV-Ray [0-9.]*' || echo POV-Ray)"
hyperfine -N --warmup 1 --runs "${RUNS:-10}" --style basic --export-json "$out/times.json" \
  -n "rt plane" "$(rt "$src/tools/bench/scenes/whitted_plane.json" rt-plane)" \
  -n "povray plane" "$(pov whitted_plane povray-plane)" \
  -n "rt boxes" "$(rt "$src/stages/05-recursion/scenes/whitted.json" rt-boxes "--accelerator bvh")" \
  -n "povray boxes" "$(pov whitted povray-boxes)" 2>&1 |
  grep -E "^Benchmark|Time \(mean|User:" || true

echo "== ratios (POV-Ray's time / rt's: above 1, rt is faster)"
jq -r '
  (.results | map({key: .command, value: {wall: .mean, cpu: ((.user // 0) + (.system // 0))}}) | from_entries) as $r
  | ["plane", "boxes"][] as $scene
  | $r["rt " + $scene] as $rt | $r["povray " + $scene] as $pov
  | "\($scene): wall \(($pov.wall / $rt.wall) * 100 | round / 100)x, CPU \(($pov.cpu / $rt.cpu) * 100 | round / 100)x "
    + "(rt \($rt.wall * 1000 | round) ms wall, \($rt.cpu * 1000 | round) ms CPU; "
    + "POV-Ray \($pov.wall * 1000 | round) ms wall, \($pov.cpu * 1000 | round) ms CPU)"
' "$out/times.json"
echo "== images: $out/{rt,povray}-{plane,boxes}.png"
