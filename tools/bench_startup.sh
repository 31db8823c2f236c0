#!/usr/bin/env bash
# Start-up and everyday-loop figures (docs/performance.md): process start of `rt`, a tiny render,
# one framework test process, and a full grade of the reference solution. Prints figures; asserts
# nothing (timings on a shared 2-core machine are not tests).
#   tools/bench_startup.sh [BUILD_DIR]        (default: build)
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$src/build}" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
command -v hyperfine >/dev/null || { echo "bench_startup: needs hyperfine (scripts/install-deps.sh)"; exit 1; }

scene=$src/stages/03-blinn-phong/scenes/direct_light.json
echo "== process start and a 64x48 render (hyperfine; user + system is the process time)"
hyperfine -N --warmup 3 --runs 20 --style basic \
  "$build/bin/rt --help" \
  "$build/bin/rt render $scene --width 64 --height 48 --threads 1 -q -o $work/tiny.png" \
  "$build/bin/framework_tests --gtest_filter=Srgb.KnownValues" 2>&1 |
  grep -E "^Benchmark|Time \(mean|User:" || true

echo "== shared libraries loaded at start (ldd)"
for b in rt framework_tests stage03_tests rt-grade; do
  [ -x "$build/bin/$b" ] && printf '%-16s %s\n' "$b" "$(ldd "$build/bin/$b" | wc -l)"
done

echo "== full grade of the reference solution, stages with a grading.json (workspace ready)"
sub=$work/submission
mkdir -p "$sub"
for dir in "$src"/stages/*/; do
  [ -f "$dir/grading.json" ] || continue
  for f in $(jq -r '.student_files[]' "$dir/stage.json"); do cp "$dir/$f" "$sub/"; done
done
"$build/bin/rt-grade" prepare >/dev/null
/usr/bin/time -f "%e s wall, %U s user, %S s system, %M KB peak RSS (rt-grade)" \
  "$build/bin/rt-grade" "$sub" --results "$work/results.json" --html "$work/report.html" \
  > "$work/grade.log" 2>&1 || { tail -5 "$work/grade.log"; exit 1; }
tail -1 "$work/grade.log"
jq -r '"score: \(.score) of \([.tests[].max_score] | add)"' "$work/results.json"
