# Sourced by the cohort tests (similarity.sh, class_cohort.sh).
# A solution disguised as a copier would: names changed, comments dropped and one of its own
# added, and intersect_box moved before intersect_sphere.
disguise() {
  sed -E 's/\bt_range\b/span/g; s/\bdiscriminant\b/disc/g; s/\bhalf_b\b/hb/g; s/\boc\b/rel/g;
          s/\bcol1\b/k1/g; s/\bcol2\b/k2/g; s/\bcol3\b/k3/g; s/\bdet_m\b/dm/g; s/\brhs\b/r0/g;
          s/\bt_near\b/enter/g; s/\bt_far\b/leave/g; s/\brecord\b/note/g; s/\bfound\b/any/g;
          s/\bnear_axis\b/ia/g; s/\bfar_axis\b/oa/g; s/\bouter\b/outer2/g' "$1" |
    sed -E '/^[[:space:]]*\/\//d; s/[[:space:]]+\/\/.*$//' |
    awk '/^bool intersect_box/ { grab = 1 }
         grab { box = box $0 "\n"; if ($0 == "}") grab = 0; next }
         { rest[++n] = $0 }
         END { for (i = 1; i <= n; ++i) {
                 if (rest[i] ~ /^bool intersect_sphere/) printf "// written by me\n%s\n", box
                 print rest[i] } }'
}
