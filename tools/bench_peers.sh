#!/usr/bin/env bash
# The renderer against the renderers a course would pick instead, side by side in one run
# (issue 51). Prints figures and asserts nothing: timings on a shared 2-core machine are figures,
# not tests. Each peer is optional; a missing one is named and skipped.
#   1. Whitted scene (tools/bench/scenes/whitted_plane.json), 1024x768, one sample a pixel, end to
#      end (start-up, parsing, rendering, PNG), on 1 and 2 threads: rt; POV-Ray 3.7
#      (tools/bench/povray/whitted_plane.pov); Tachyon (tools/bench/tachyon/whitted_plane.dat, its
#      own format, without refraction). hyperfine's mean wall time and user + system time, rays per
#      second by POV-Ray's count of the scene's rays (Tachyon's glass passes rays straight on, so
#      its count is close but not the same), and each peer's own render time.
#   2. Path tracing (tools/bench/scenes/cornell_diffuse.json, 200x200, 2 threads): rt against
#      Blender's Cycles (tools/bench/cycles/cornell_diffuse.py) at 16, 64 and 256 samples, each
#      image's RMS error against Cycles at REF_SPP samples (default 2048), paths per second, and
#      Cycles' error at rt's render times (log-log interpolation between its own points).
#   3. BVH traversal against Embree: rt-bench's table for a 100,000-triangle torus.
#   tools/bench_peers.sh [BUILD_DIR] [OUT_DIR]      (defaults: build, /tmp/rt-bench-peers)
# Environment: RUNS (hyperfine runs, default 10), REF_SPP (Cycles reference, default 2048).
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$src/build}" && pwd)
out=${2:-/tmp/rt-bench-peers}
runs=${RUNS:-10}
ref_spp=${REF_SPP:-2048}
for tool in hyperfine jq oiiotool; do
  command -v "$tool" > /dev/null || { echo "bench_peers: needs $tool (scripts/install-deps.sh)"; exit 1; }
done
mkdir -p "$out"
have() { command -v "$1" > /dev/null || { echo "  ($1 not installed: apt-get install $2)"; return 1; }; }
ms() { awk -v s="$1" 'BEGIN {printf "%.0f", s * 1000}'; }
echo "== machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), load $(cut -d' ' -f1-3 /proc/loadavg)"

# ---------------------------------------------------------------- 1. Whitted scene
echo "== 1. Whitted scene, 1024x768, end to end"
whitted=$src/tools/bench/scenes/whitted_plane.json
commands=()
for t in 1 2; do
  commands+=(-n "rt, $t thread(s)" "$build/bin/rt render $whitted --threads $t -q -o $out/rt-whitted.png")
done
if have povray povray; then
  for t in 1 2; do
    commands+=(-n "POV-Ray, $t thread(s)"
               "povray -D -GA +WT$t +W1024 +H768 +FN +I$src/tools/bench/povray/whitted_plane.pov +O$out/povray-whitted.png")
  done
fi
if have tachyon tachyon; then
  for t in 1 2; do
    commands+=(-n "Tachyon, $t thread(s)"
               "tachyon $src/tools/bench/tachyon/whitted_plane.dat -numthreads $t -format PNG -o $out/tachyon-whitted.png")
  done
fi
hyperfine -N --warmup 1 --runs "$runs" --style none --export-json "$out/whitted.json" "${commands[@]}" > /dev/null 2>&1
rays=""
if command -v povray > /dev/null; then
  (cd "$out" && povray -D +WT1 +W1024 +H768 +FN +I"$src/tools/bench/povray/whitted_plane.pov" +O"$out/povray-whitted.png" > "$out/povray.log" 2>&1)
  camera=$(awk '/^Rays:/ {print $2}' "$out/povray.log")
  shadow=$(awk '/^Shadow Ray Tests:/ {print $4}' "$out/povray.log")
  rays=$((camera + shadow))
  echo "  POV-Ray's count of the scene's rays: $camera traced (camera, reflected, refracted) + $shadow shadow tests = $rays"
  echo "  POV-Ray's own trace time, 1 thread: $(awk '/Trace Time:/ {v = $(NF - 1); gsub(/[()]/, "", v); print v}' "$out/povray.log") s"
fi
if command -v tachyon > /dev/null; then
  echo "  Tachyon's own ray tracing time, 1 thread: $(tachyon "$src/tools/bench/tachyon/whitted_plane.dat" -numthreads 1 -format PNG \
    -o "$out/tachyon-whitted.png" 2>&1 | awk '/Ray Tracing Time:/ {print $4}') s"
fi
jq -r --arg rays "${rays:-0}" '
  def fmt(x): (x * 1000 | round | tostring) + " ms";
  .results[] as $r
  | ($r.user + $r.system) as $cpu
  | "  \($r.command | . + " " * (22 - length)) wall \(fmt($r.mean))  CPU \(fmt($cpu))"
    + (if ($rays | tonumber) > 0 then "  \((($rays | tonumber) / $r.mean / 1e6 * 100 | round) / 100) Mrays/s (wall)" else "" end)
' "$out/whitted.json"
echo "  ratios, the peer's time over rt's at the same thread count (above 1: rt is faster):"
jq -r '
  (.results | map({key: .command, value: {wall: .mean, cpu: (.user + .system)}}) | from_entries) as $r
  | ["POV-Ray", "Tachyon"][] as $peer | [1, 2][] as $t
  | "\($peer), \($t) thread(s)" as $name | $r[$name] as $p | $r["rt, \($t) thread(s)"] as $rt
  | select($p != null)
  | "    \($name): wall \(($p.wall / $rt.wall * 100 | round) / 100)x, CPU \(($p.cpu / $rt.cpu * 100 | round) / 100)x"
' "$out/whitted.json"

# ---------------------------------------------------------------- 2. path tracing against Cycles
echo "== 2. path tracing, tools/bench/scenes/cornell_diffuse.json, 200x200, 2 threads"
cornell=$src/tools/bench/scenes/cornell_diffuse.json
cycles() {  # cycles SAMPLES OUT.exr SEED: prints the render seconds (without Blender's start-up)
  blender -b --factory-startup --python "$src/tools/bench/cycles/cornell_diffuse.py" -- \
    "$out/cycles-raw.exr" "$1" 2 "$3" 2>&1 | awk '/^cycles: render/ {print $3}'
  oiiotool "$out/cycles-raw.exr" --ch R,G,B -o "$2"
}
rmse() { oiiotool "$1" "$2" --diff 2>&1 | awk '/RMS error/ {print $4}'; }
if have blender blender; then
  reference=$out/cycles-reference-$ref_spp.exr
  if [[ ! -f $reference ]]; then
    echo "  the reference: Cycles at $ref_spp samples, another seed ($(cycles "$ref_spp" "$reference" 99) s)"
  fi
  printf "  %-8s %7s %10s %10s %12s\n" renderer samples "render s" "RMS error" "paths/s"
  : > "$out/cornell.txt"
  for spp in 16 64 256; do
    seconds=$("$build/bin/rt" render "$cornell" --spp "$spp" --threads 2 -o "$out/rt-$spp.exr" |
              sed -n 's/.* \([0-9.]*\) s -> .*/\1/p')
    echo "rt $spp $seconds $(rmse "$reference" "$out/rt-$spp.exr")" >> "$out/cornell.txt"
    seconds=$(cycles "$spp" "$out/cycles-$spp.exr" 1)
    echo "Cycles $spp $seconds $(rmse "$reference" "$out/cycles-$spp.exr")" >> "$out/cornell.txt"
  done
  awk '{printf "  %-8s %7d %10s %10s %12.0f\n", $1, $2, $3, $4, 200 * 200 * $2 / $3}' "$out/cornell.txt"
  # Equal time: Cycles' error at each of rt's times, interpolated in log-log between its points.
  awk '$1 == "rt" {rt_t[++n] = $3; rt_e[n] = $4; rt_s[n] = $2}
       $1 == "Cycles" {c_t[++m] = $3; c_e[m] = $4}
       END {
         for (i = 1; i <= n; ++i) {
           t = rt_t[i]; k = 1
           while (k < m - 1 && c_t[k + 1] < t) ++k
           f = (log(t) - log(c_t[k])) / (log(c_t[k + 1]) - log(c_t[k]))
           e = exp(log(c_e[k]) + f * (log(c_e[k + 1]) - log(c_e[k])))
           printf "  equal time, %.2f s (rt at %d samples): rt %.4f, Cycles %.4f: Cycles / rt %.2fx\n", t, rt_s[i], rt_e[i], e, e / rt_e[i]
         }
       }' "$out/cornell.txt"
  echo "  (render s: rt's own summary, scene loading included; Cycles' bpy.ops.render.render, Blender's start-up not)"
fi

# ---------------------------------------------------------------- 3. BVH against Embree
echo "== 3. BVH traversal against Embree (rt-bench, 100,000-triangle torus, 1024x768 rays)"
"$build/bin/rt-bench" --triangles 100000 --repeat 3 2>&1 |
  grep -E "^  (back-end|(bvh|bvh-tuned|embree) +[0-9])|^ratios" || true
echo "== images: $out"
