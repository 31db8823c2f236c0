# stage_points N: the points of stage N, worked out here rather than written down: grading.json's
# points for each unit group times its tests (the instructor's test lists that the grading
# workspace keeps, under the group's include and exclude patterns), plus its scenes' points.
# Sourced by case_lib.sh and tools/rehearsal.sh; needs src and a prepared workspace
# (RT_GRADE_CACHE, default SRC/build/grader-cache).
stage_points() {
  local json expected group points count name total=0
  json=$(echo "$src"/stages/"$(printf %02d "$1")"-*/grading.json)
  expected=${RT_GRADE_CACHE:-$src/build/grader-cache}/private/expected
  while read -r group; do
    points=$(jq -r '.points // 1' <<< "$group")
    mapfile -t inc < <(jq -r '(.include // ["*"])[]' <<< "$group")
    mapfile -t exc < <(jq -r '(.exclude // [])[]' <<< "$group")
    count=0
    while read -r name; do
      # A test counts when some include pattern matches and no exclude pattern does.
      # shellcheck disable=SC2053 # gtest patterns are globs
      local in=0 out=0
      for p in "${inc[@]}"; do [[ $name == $p ]] && { in=1; break; }; done
      for p in "${exc[@]}"; do [[ $name == $p ]] && { out=1; break; }; done
      (( in && !out )) && count=$((count + 1))
    done < <(jq -r '.[]' "$expected/$(jq -r .binary <<< "$group").json")
    total=$(awk -v t="$total" -v c="$count" -v p="$points" 'BEGIN { print t + c * p }')
  done < <(jq -c '.unit_tests[]' "$json")
  awk -v t="$total" -v s="$(jq '[.scenes[] | .points // 1] | add // 0' "$json")" 'BEGIN { print t + s }'
}

