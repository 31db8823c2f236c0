#!/usr/bin/env bash
# Remote.<binary>.HoldsNoStudentCode: a grading judge defines no function of the libraries that
# hold or run student code (the stage objects, render/, the GPU renderer that runs the student's
# GLSL) other than its proxies of them (librt_judge.a, framework/stage_api/calls.h), and it holds
# those proxies (one object defines them all, so a student definition beside them could not
# link). Catches a build change that would put student code in the process that decides verdicts.
#   check_judge_links.sh JUDGE JUDGE_ARCHIVE STUDENT_SIDE_ARCHIVE...
set -euo pipefail
judge=$1 proxies=$2
shift 2
defined() { nm -C --defined-only "$@" 2>/dev/null | awk '$2 == "T" { $1 = ""; $2 = ""; sub(/^  /, ""); print }' | sort -u; }
judge_defines=$(defined "$judge") proxy_defines=$(defined "$proxies")
student_side=$(comm -23 <(defined "$@") <(echo "$proxy_defines"))
found=$(comm -12 <(echo "$judge_defines") <(echo "$student_side"))
for needed in 'rt::remote::proxy_key(void const*)' 'rt::intersect_sphere(rt::Ray const&, rt::Sphere const&, rt::Interval, rt::Hit&)'; do
  if ! grep -qxF "$needed" <<< "$proxy_defines" || ! grep -qxF "$needed" <<< "$judge_defines"; then
    echo "$(basename "$judge") does not hold the judge's proxies ($needed)"
    exit 1
  fi
done
if [ -n "$found" ]; then
  echo "$(basename "$judge") links code that holds or runs student code:"
  echo "$found" | head -20
  exit 1
fi
echo "$(basename "$judge"): none of the $(echo "$student_side" | wc -l) student-side functions, only proxies"
