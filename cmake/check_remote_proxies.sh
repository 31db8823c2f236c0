#!/usr/bin/env bash
# Framework.Remote.EveryStageFunctionHasAProxy: every global function the student files define
# (the stage APIs, as librt_stages.a holds them) has a judge proxy in librt_judge.a, generated
# from framework/stage_api/calls.h. A new student function missing from the lists fails here,
# before a grading judge could call the worker's side of it.
#   check_remote_proxies.sh STAGES_ARCHIVE JUDGE_ARCHIVE
set -euo pipefail
defined() { nm -C --defined-only "$1" | awk '$2 == "T" { $1 = ""; $2 = ""; sub(/^  /, ""); print }' | sort -u; }
missing=$(comm -23 <(defined "$1") <(defined "$2"))
if [ -n "$missing" ]; then
  echo "stage functions without a proxy (add them to framework/stage_api/calls.h):"
  echo "$missing"
  exit 1
fi
echo "every one of the $(defined "$1" | wc -l) stage functions has a proxy"
