#!/usr/bin/env bash
# Autolab's grading, from the folder Tango runs `make` in: finds the hand-in (a .zip, a .tar or a
# loose file), grades it, and keeps everything but the score lines off stdout (the grader's log
# goes to stderr, capped, so the output stays far below Autolab's 1000 KiB).
here=$PWD
bundle=$here/rt-grade
. "$bundle/settings.sh"
handin=""
for f in "$here"/*; do
  case ${f##*/} in autograde.tar | Makefile | autograde-Makefile | rt-grade | handin-files) continue ;; esac
  [ -f "$f" ] && { handin=$f; break; }
done
submission=$here/handin-files
rm -rf "$submission" && mkdir -p "$submission"
case $handin in
  "") ;;
  *.zip) submission=$handin ;;
  *.tar | *.tar.gz | *.tgz) tar -xf "$handin" -C "$submission" --no-same-owner --no-same-permissions 2> /dev/null ;;
  *) cp "$handin" "$submission/" ;;
esac
# stdout: only rt-grade's score lines (kept in scores.log too); its log goes to grader.log.
set -o pipefail
"$bundle/bin/rt-grade" "$submission" --source "$bundle/cache/workspace/src" --cache "$bundle/cache" \
  --jobs 1 --quiet ${stages:+--stages "$stages"} ${problem_names:+--problem-names "$problem_names"} \
  --autolab-scores --html "$here/report.html" 2> "$here/grader.log" | tee "$here/scores.log"
code=$?
if [ $code -ne 0 ]; then
  # The grader's own failure, for the course staff: its log, then the last score line again.
  echo "rt-grade stopped (exit $code); its log:"
  head -c 20000 "$here/grader.log"
  echo
  last=$(tail -n 1 "$here/scores.log" 2> /dev/null)
  case $last in '{"scores"'*) echo "$last" ;; *) echo '{"scores": {}, "scoreboard": [0]}' ;; esac
fi
exit 0
