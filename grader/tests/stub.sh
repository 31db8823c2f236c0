# Sourced by the grader's case scripts (case_lib.sh) and tools/class_size.sh.
# The starter (stub) version of a student file: what `rt-grade release` writes.
stub() {
  awk '/^[ \t]*\/\/ BEGIN SOLUTION[ \t]*$/ {s=1; next}
       /^[ \t]*\/\/ STUB[ \t]*$/ {s=2; next}
       /^[ \t]*\/\/ END SOLUTION[ \t]*$/ {s=0; next}
       s==1 {next}
       s==2 {sub(/\/\/ ?/, "")}
       {print}' "$1"
}
