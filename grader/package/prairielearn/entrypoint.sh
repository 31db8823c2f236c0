#!/usr/bin/env bash
# PrairieLearn's external grader entry point: grades /grade/student, writes
# /grade/results/results.json and exits 0 in every case (PrairieLearn reads the file, not the
# exit code). rt-grade writes "gradable": false first and the scores at the end; if rt-grade
# itself cannot run, this script writes the not-gradable result.
root=${RT_PL_ROOT:-/grade}
bundle=${RT_BUNDLE:-/grader/rt-grade}
results=$root/results/results.json
mkdir -p "$root/results"
rm -f "$results"
. "$bundle/settings.sh" || true
data=()
[ -f "$root/data/data.json" ] && data=(--prairielearn-data "$root/data/data.json")
"$bundle/bin/rt-grade" "$root/student" --source "$bundle/cache/workspace/src" \
  --cache "$bundle/cache" --jobs 1 --quiet ${stages:+--stages "$stages"} "${data[@]}" \
  --prairielearn-results "$results" > "$root/results/grader.log" 2>&1
code=$?
if [ ! -s "$results" ]; then
  printf '{"gradable": false, "score": 0, "message": "%s", "tests": []}\n' \
    "The grader could not run (exit $code; a problem of the grader, not of your submission): this submission does not count." \
    > "$results"
fi
exit 0
