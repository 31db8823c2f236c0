# A class as Gradescope's "Export Submissions" lays it out, built from the instructor's solution
# (class_cohort.sh, slurm_class.sh): one folder per submission and submission_metadata.yml.
# Source it after case_lib.sh and disguise.sh; `add_class` adds thirteen submissions of stages 01
# and 02 (twelve students: one submitted twice), `write_export` writes the metadata and
# $work/export.zip.
exp=$work/export/assignment_61_export
n=0 metadata=""

# submission NAME SID SCORE MINUTES: a new submission folder of NAME (its files go in $dir),
# made MINUTES after 09:00 on 2026-12-01, scored SCORE by Gradescope before the regrade.
submission() {
  n=$((n + 1)); dir=$exp/submission_$n; mkdir -p "$dir"
  metadata+="submission_$n:
  :submitters:
  - :name: $1
    :sid: '$2'
    :email: $(tr 'A-Z ' 'a-z.' <<< "$1")@example.com
  :created_at: 2026-12-01 $(printf '%02d:%02d' $((9 + $4 / 60)) $(($4 % 60))):00.000000000 -0800
  :score: $3
"
}
ref1() { cp "$src/$s1/camera_rays.cpp" "$dir/"; }
ref2() { cp "$src/$s2/intersections.cpp" "$dir/"; }
stub1() { stub "$src/$s1/camera_rays.cpp" > "$dir/camera_rays.cpp"; }
stub2() { stub "$src/$s2/intersections.cpp" > "$dir/intersections.cpp"; }

add_class() {
  submission "Ada Byron" 101 10 0;        stub1; stub2   # her first try, replaced by the next
  submission "Ada Byron" 101 84 90;       ref1; ref2
  submission "Bo Chen" 102 84 10;         ref1; disguise "$src/$s2/intersections.cpp" > "$dir/intersections.cpp"
  submission "Ivo Petrov" 103 84 20;      ref1
  disguise "$src/$s2/intersections.cpp" | sed 's/\bspan\b/window/g; s/\bdisc\b/delta/g' > "$dir/intersections.cpp"
  submission "Cy Young" 104 84 30;        ref1; cp "$src/$s2/hidden/similarity_independent.cpp" "$dir/intersections.cpp"
  submission "Dee Okafor" 105 0 40;       stub1; stub2
  submission "Eve Adams" 106 18 50;       ref1                       # stage 02 not handed in
  submission "Fay Wong" 107 70 60;        ref2                       # pixel corners, not centres
  sed 's|Vec2 pixel, ImageSize size) {|Vec2 pixel, ImageSize size) {\n    pixel -= Vec2(0.5);|' \
    "$src/$s1/camera_rays.cpp" > "$dir/camera_rays.cpp"
  submission "Gus Lind" 108 76 70;        ref1                       # normals not flipped to the ray
  sed 's|hit.set_face_normal(ray, \(.*\));|hit.normal = \1; hit.front_face = true;|' \
    "$src/$s2/intersections.cpp" > "$dir/intersections.cpp"
  submission "Hal Berg" 109 18 80;        ref1; { ref2; echo 'int broken = ;' >> "$dir/intersections.cpp"; }
  submission "Jo Marsh" 110 66 100;       stub1; ref2
  submission "Kim Sato" 111 0 110;        stub1                      # a start, nothing more
  submission "Lu Diaz" 112 "" 120;        ref1; ref2                 # not yet scored by Gradescope
}

write_export() {
  printf '%s' "$metadata" > "$exp/submission_metadata.yml"
  (cd "$work/export" && zip -q -r ../export.zip .) || fail "zip the export"
}
