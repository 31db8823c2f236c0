#!/usr/bin/env bash
# The mutation corpus (grader/tests/mutations/, docs/grading.md "Grading power"): realistic
# mistakes a student makes, each of which must lose points with a message that names its cause,
# and correct alternatives to the reference, each of which must keep full marks.
#
#   mutation_corpus.sh BIN_DIR SRC_DIR STAGE [NAME...]
#   mutation_corpus.sh BIN_DIR SRC_DIR --slice NN/NAME...
#
# Grades every mutation of stage STAGE (grader/tests/mutations/NN/*.mutation), or only the NAMEs
# given, in one `rt-grade batch` (each mutation is one submission: the stage's reference files
# with the mutation's edits), then prints a line per mutation and the score:
#   mistakes caught: C of N; alternatives kept: K of M
# and fails unless every mistake is caught and every alternative kept.
# --slice: the mutations named, at most one per stage, in one submission graded once. A stage is
# graded with the reference's files of the stages before it, so each stage's tests see only its
# own mutation: CI's share of the corpus (Grader.Mutations.slice) costs one grading.
#
# A .mutation file: a comment saying what the student did, `key: value` lines, then one or more
# find/replace pairs, each text a block of whole lines that must occur exactly once in the file:
#   # What the student wrote and why it is wrong (or why it is right).
#   kind: mistake                  mistake | alternative
#   file: blinn_phong.cpp          a student file of the stage (stage.json)
#   cause: specular|half vector    (mistakes) an extended regex, matched without case against
#                                  the output of the tests that lost points
#   find:
#   <the reference's lines>
#   replace:
#   <the student's lines>
set -uo pipefail
if [[ $# -lt 3 ]]; then
  echo "usage: $0 BIN_DIR SRC_DIR STAGE [NAME...] | --slice NN/NAME..." >&2
  exit 2
fi
bin=$1 src=$2
corpora=$(cd "$(dirname "$0")" && pwd)/mutations

# stage_folder NN: stages/NN-name of the tree.
stage_folder() {
  local dir
  dir=$(cd "$src" && echo stages/$(printf '%02d' "$((10#$1))")-*)
  [[ -d $src/$dir ]] || { echo "FAIL: no stage $1 under $src/stages" >&2; return 1; }
  echo "$dir"
}

work=$(mktemp -d /tmp/rt-mutations-XXXXXX)
trap '[[ -n ${RT_KEEP_MUTATIONS:-} ]] || rm -rf "$work"' EXIT

# field FILE KEY: the value of a `key: value` header line.
field() { sed -n "s/^$2: *//p" "$1" | head -n 1; }

# apply MUTATION TARGET: the find/replace pairs applied to TARGET. Each find text must occur
# exactly once: a reference that changed under a mutation is reported, never silently skipped.
apply() {
  local mutation=$1 target=$2 pairs=$work/pairs
  rm -rf "$pairs" && mkdir -p "$pairs"
  awk -v dir="$pairs" '
    /^find:[ \t]*$/ { n++; out = dir "/" n ".find"; printf "" > out; next }
    /^replace:[ \t]*$/ { out = dir "/" n ".replace"; printf "" > out; next }
    out != "" { print > out }' "$mutation"
  local count=0 find replace text block rest
  for find in "$pairs"/*.find; do
    [[ -e $find ]] || break
    replace=${find%.find}.replace
    [[ -e $replace ]] || { echo "$mutation: a find: block without its replace: block"; return 1; }
    text=$(cat "$target")
    block=$(cat "$find")
    if [[ $text != *"$block"* ]]; then
      echo "$mutation: its find: block ($(head -n 1 "$find" | sed 's/^ *//')...) is not in" \
           "$(basename "$target"): update the mutation to the reference"
      return 1
    fi
    rest=${text#*"$block"}
    if [[ $rest == *"$block"* ]]; then
      echo "$mutation: its find: block occurs more than once in $(basename "$target"): add a line of context"
      return 1
    fi
    printf '%s\n' "${text/"$block"/"$(cat "$replace")"}" > "$target"
    count=$((count + 1))
  done
  [[ $count -gt 0 ]] || { echo "$mutation: no find:/replace: pair"; return 1; }
}

declare -A kind cause stage_of
# prepare NN NAME SUBMISSION: the stage's student files with the mutation applied, in
# SUBMISSION/stages/NN-name.
prepare() {
  local nn=$1 name=$2 submission=$3 stage_dir m file f
  stage_dir=$(stage_folder "$nn") || exit 1
  m=$corpora/$(printf '%02d' "$((10#$nn))")/$name.mutation
  [[ -f $m ]] || { echo "FAIL: no mutation $m"; exit 1; }
  stage_of[$name]=$((10#$nn))
  kind[$name]=$(field "$m" kind)
  cause[$name]=$(field "$m" cause)
  file=$(field "$m" file)
  case ${kind[$name]} in
    mistake) [[ -n ${cause[$name]} ]] || { echo "FAIL: $m: a mistake needs a cause: line"; exit 1; } ;;
    alternative) ;;
    *) echo "FAIL: $m: kind: must be mistake or alternative"; exit 1 ;;
  esac
  mapfile -t student_files < <(jq -r '.student_files[]' "$src/$stage_dir/stage.json")
  printf '%s\n' "${student_files[@]}" | grep -qx "$file" ||
    { echo "FAIL: $m: file: $file is not a student file of $stage_dir (${student_files[*]})"; exit 1; }
  mkdir -p "$submission/$stage_dir"
  for f in "${student_files[@]}"; do cp "$src/$stage_dir/$f" "$submission/$stage_dir/$f"; done
  apply "$m" "$submission/$stage_dir/$file" || { echo "FAIL: the mutation does not apply"; exit 1; }
  cmp -s "$src/$stage_dir/$file" "$submission/$stage_dir/$file" && { echo "FAIL: $m changes nothing"; exit 1; }
}

names=()
declare -A results_of
start=$(date +%s)
if [[ $3 == --slice ]]; then
  shift 3
  stages=()
  for pair in "$@"; do
    [[ $pair == */* ]] || { echo "FAIL: --slice takes NN/NAME, not $pair"; exit 1; }
    nn=${pair%%/*} name=${pair#*/}
    [[ " ${stages[*]} " != *" $((10#$nn)) "* ]] || { echo "FAIL: two mutations of stage $nn in the slice"; exit 1; }
    stages+=("$((10#$nn))")
    names+=("$name")
    prepare "$nn" "$name" "$work/submission"
    results_of[$name]=$work/results.json
  done
  list=$(IFS=,; echo "${stages[*]}")
  "$bin/rt-grade" "$work/submission" --stages "$list" --quiet --results "$work/results.json" \
    > "$work/grade.log" 2>&1 || { cat "$work/grade.log"; echo "FAIL: rt-grade"; exit 1; }
  echo "graded ${#names[@]} mutations of stages $list in one grading in $(( $(date +%s) - start )) s"
  label="slice of stages $list"
else
  stage=$((10#$3))
  shift 3
  [[ -d $corpora/$(printf '%02d' "$stage") ]] || { echo "FAIL: no mutations for stage $stage in $corpora"; exit 1; }
  names=("$@")
  if [[ ${#names[@]} -eq 0 ]]; then
    for m in "$corpora/$(printf '%02d' "$stage")"/*.mutation; do names+=("$(basename "$m" .mutation)"); done
  fi
  for name in "${names[@]}"; do
    prepare "$stage" "$name" "$work/submissions/$name"
    results_of[$name]=$work/grades/$name/results.json
  done
  "$bin/rt-grade" batch "$work/submissions" --out "$work/grades" --stages "$stage" --jobs 2 \
    > "$work/batch.log" 2>&1 || { cat "$work/batch.log"; echo "FAIL: rt-grade batch"; exit 1; }
  echo "graded ${#names[@]} mutations of stage $stage in $(( $(date +%s) - start )) s"
  label="stage $stage"
fi

# The tests of a mutation's stage in its results (a slice's results hold every stage's).
tests_of() { jq --arg tag "$(printf 'stage%02d' "${stage_of[$1]}")" "[.tests[] | select(.tags | index(\$tag))] | $2" "${results_of[$1]}"; }
# The failing tests of the mutation's stage, a line each: name and first line of output.
lost_lines() {
  tests_of "$1" '.[] | select(.score < .max_score) | "         \(.name): \(.output | split("\n")[0])"' | jq -r .
}

mistakes=0 caught=0 alternatives=0 kept=0
for name in "${names[@]}"; do
  [[ -s ${results_of[$name]} ]] || { echo "MISSED   $name: no results.json"; continue; }
  score=$(tests_of "$name" '[.[].score] | add')
  max=$(tests_of "$name" '[.[].max_score] | add')
  if [[ ${kind[$name]} == alternative ]]; then
    alternatives=$((alternatives + 1))
    if [[ $score == "$max" ]]; then
      kept=$((kept + 1))
      echo "kept     $name: $score of $max"
    else
      echo "LOST     $name (a correct alternative): $score of $max; the tests that took points:"
      lost_lines "$name"
    fi
    continue
  fi
  mistakes=$((mistakes + 1))
  # The failing tests' names and messages, without the handout links every failure carries
  # (a section's name, such as #diffuse-and-specular, is not a message naming the cause).
  failing=$(tests_of "$name" '.[] | select(.score < .max_score) | .name + "\n" + .output' | jq -r . |
            grep -vE 'Read the handout: |The handout on what this test checks: ')
  if [[ $score == "$max" ]]; then
    echo "MISSED   $name: full marks ($max)"
  elif ! grep -qiE -- "${cause[$name]}" <<< "$failing"; then
    echo "UNNAMED  $name: $score of $max, but no failing test's message matches /${cause[$name]}/; they say:"
    lost_lines "$name" | head -n 8
  else
    caught=$((caught + 1))
    echo "caught   $name: $score of $max ($(tests_of "$name" '[.[] | select(.score < .max_score)] | length') tests)"
  fi
done
echo "$label: mistakes caught: $caught of $mistakes; alternatives kept: $kept of $alternatives"
[[ $caught -eq $mistakes && $kept -eq $alternatives ]]
