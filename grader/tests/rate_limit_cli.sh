#!/usr/bin/env bash
# rt-grade --max-per-day on Gradescope's metadata: a refused submission's results.json is valid
# under Gradescope's schema (results_check), keeps the latest graded score and tests, says when
# the next graded submission is possible, and is the same on a rerun.
#   rate_limit_cli.sh RT_GRADE RESULTS_CHECK
set -euo pipefail
grade=$1 check=$2
work=$(mktemp -d /tmp/rt-grade-rate-XXXXXX)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/submission"
cat > "$work/submission_metadata.json" <<'JSON'
{"id": 42, "created_at": "2026-12-04T12:00:00.123456-08:00",
 "assignment": {"title": "Stage 01", "total_points": "10.0"},
 "users": [{"email": "student@example.com", "id": 1, "name": "A Student"}],
 "previous_submissions": [
  {"submission_time": "2026-12-04T09:00:00-08:00", "score": 4.0,
   "results": {"score": 4.0, "tests": [{"name": "Stage 01 Perspective.PixelCentersAreSymmetric",
     "number": "1.1", "score": 4.0, "max_score": 10.0, "status": "failed", "output": "",
     "output_format": "text", "tags": ["stage01"], "visibility": "visible"}]}},
  {"submission_time": "2026-12-04T10:00:00-08:00", "score": 10.0,
   "results": {"score": 10.0, "tests": [{"name": "Stage 01 Perspective.PixelCentersAreSymmetric",
     "number": "1.1", "score": 10.0, "max_score": 10.0, "status": "passed", "output": "",
     "output_format": "text", "tags": ["stage01"], "visibility": "visible"}]}}]}
JSON
run() {
  "$grade" "$work/submission" --quiet --max-per-day "$1" --metadata "$work/submission_metadata.json" \
    --results "$work/$2"
}
run 2 first.json
"$check" "$work/first.json" --score-min 10 --score-max 10 --contains "not graded" \
  --contains "2026-12-05 17:00 UTC" --test-passed "Stage 01 Perspective.PixelCentersAreSymmetric"
run 2 again.json
cmp "$work/first.json" "$work/again.json" || { echo "FAIL: a rerun answered differently"; exit 1; }
# Without --metadata the limit is refused on the command line, in one line.
if "$grade" "$work/submission" --max-per-day 2 2> "$work/err.txt"; then
  echo "FAIL: --max-per-day without --metadata was accepted"; exit 1
fi
[ "$(wc -l < "$work/err.txt")" -eq 1 ] || { cat "$work/err.txt"; echo "FAIL: not one line"; exit 1; }
echo "rate limit: refused with the latest graded score, valid results.json, same on a rerun"
