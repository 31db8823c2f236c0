#!/usr/bin/env bash
# The grading bundle's audit: would it load and link on Ubuntu 22.04 (Gradescope's image) as well
# as on Debian 12? Checked without Ubuntu, from the files themselves:
#   1. every ELF program and shared library needs at most GLIBC_2.35 (Ubuntu 22.04's glibc),
#      GLIBCXX_3.4.30 and CXXABI_1.3.13 (GCC 12's libstdc++, which g++-12 brings to both);
#   2. every library they need is in the bundle or is a soname target_packages.txt lets the
#      target provide;
#   3. every object and archive linked on the target calls no C library function newer than
#      2.35 (its versions are bound there, by the target's linker);
#   4. the packages the bundle asks for (BUNDLE/packages.txt) are all on target_packages.txt.
# Prints one line per finding, naming the file and the fix; exits 1 when there is one.
#
#   audit_bundle.sh BUNDLE TARGET_PACKAGES_TXT
set -euo pipefail
trap 'echo "audit: stopped at line $LINENO ($BASH_COMMAND failed): the audit itself broke, not the bundle"' ERR

bundle=${1:?usage: audit_bundle.sh BUNDLE TARGET_PACKAGES_TXT}
list=${2:?usage: audit_bundle.sh BUNDLE TARGET_PACKAGES_TXT}
[ -d "$bundle/cache/runtime/lib" ] || { echo "audit: $bundle is not a grading bundle (no cache/runtime/lib)"; exit 2; }

# Ubuntu 22.04's ceilings.
max_glibc=2.35 max_glibcxx=3.4.30 max_cxxabi=1.3.13
findings=0
finding() { echo "audit: $*"; findings=$((findings + 1)); }

# awk: is version a (a.b.c) after version b?
after='function after(a, b,   x, y, i) {
  split(a, x, "."); split(b, y, ".")
  for (i = 1; i <= 4; i++) if (x[i] + 0 != y[i] + 0) return x[i] + 0 > y[i] + 0
  return 0 }'

allowed_sonames=$(grep -v '^#' "$list" | awk -F'|' 'NF == 4 {print $3}' | tr ' ' '\n' | grep -v '^-\?$' | sort -u)
allowed_packages=$(grep -v '^#' "$list" | awk -F'|' 'NF == 4 {gsub(/ /, "", $1); print $1}' | sort -u)

# Every ELF file by its type, from one readelf run (archive members read as "File: a.a(m.o)").
elfs=() objects=()
while IFS=$'\t' read -r kind f; do
  if [ "$kind" = REL ]; then objects+=("$f"); else elfs+=("$f"); fi
done < <(find "$bundle" -type f -print0 | xargs -0 readelf -h 2> /dev/null |
  awk '/^File: / {file = substr($0, 7); sub(/\(.*\)$/, "", file)}
       /^  Type:/ {print ($2 == "REL" ? "REL" : "ELF") "\t" file}' | sort -u)
# The sonames the target's packages provide, looked up in bash (not a grep per library).
declare -A allowed
for soname in $allowed_sonames; do allowed[$soname]=1; done
# Each tool reads every file in one run (a process per file took 15 s per audit here). With
# several files, readelf heads each file's part with "File: PATH"; with one it does not.
heads='BEGIN { file = first } /^File: / { file = substr($0, 7) }'

if [ ${#elfs[@]} -gt 0 ]; then
  # 1: the versions each program and library needs from the C and C++ libraries.
  while IFS=$'\t' read -r f version max; do
    finding "${f#"$bundle"/} needs $version, newer than Ubuntu 22.04's $max: ship a build without it, or leave it out of the bundle"
  done < <(readelf -V -W "${elfs[@]}" 2>/dev/null |
    awk -v first="${elfs[0]}" -v glibc="$max_glibc" -v glibcxx="$max_glibcxx" -v cxxabi="$max_cxxabi" "$after $heads"'
      /^File: / { needs = 0 }
      /Version needs section/ { needs = 1 }
      needs && match($0, /Name: (GLIBC|GLIBCXX|CXXABI)_[0-9.]+/) {
        name = substr($0, RSTART + 6, RLENGTH - 6)
        if (seen[file, name]++) next
        base = name; sub(/_.*/, "", base); v = substr(name, length(base) + 2)
        max = base == "GLIBC" ? glibc : base == "GLIBCXX" ? glibcxx : cxxabi
        if (after(v, max)) print file "\t" name "\t" base "_" max }')
  # 2: the libraries each needs, in the bundle or provided by a package of the target list.
  while IFS=$'\t' read -r f needed; do
    [ -e "$bundle/cache/runtime/lib/$needed" ] && continue
    [ -n "${allowed[$needed]:-}" ] && continue
    finding "${f#"$bundle"/} needs $needed, which is neither in cache/runtime/lib nor provided by a package of target_packages.txt: ship it (rt-grade package does, for what ldd finds) or add its package there with the reason"
  done < <(readelf -d -W "${elfs[@]}" 2>/dev/null |
    awk -v first="${elfs[0]}" "$heads"'
      /\(NEEDED\)/ && match($0, /\[.*\]/) { print file "\t" substr($0, RSTART + 1, RLENGTH - 2) }')
fi

# 3: objects and archives, whose C library calls are bound by the target's linker.
libc=$(ldconfig -p | awk '/libc\.so\.6 .*x86-64/ && !n++ {print $NF}')  # no early exit: SIGPIPE + pipefail
libm=$(ldconfig -p | awk '/libm\.so\.6 .*x86-64/ && !n++ {print $NF}')
# Functions the C library first offers after 2.35 (they have no older version).
too_new=$(objdump -T "$libc" "$libm" |
  awk -v max="$max_glibc" "$after"'
    NF >= 2 && $(NF-1) ~ /GLIBC_[0-9]/ {
      v = $(NF-1); gsub(/[()]/, "", v); v = substr(v, 7)
      if (!($NF in oldest) || after(oldest[$NF], v)) oldest[$NF] = v }
    END { for (s in oldest) if (after(oldest[s], max)) print s }' | sort -u)
if [ -n "$too_new" ] && [ ${#objects[@]} -gt 0 ]; then
  # nm -A: "FILE: U symbol", or "ARCHIVE:MEMBER: U symbol"; the finding names the file.
  while IFS=$'\t' read -r f sym; do
    finding "${f#"$bundle"/} calls $sym, which Ubuntu 22.04's C library (2.35) does not have: avoid it in code linked on the target"
  done < <(nm -u -A "${objects[@]}" 2>/dev/null |
    awk -v list="$too_new" '
      BEGIN { n = split(list, names, "\n"); for (i = 1; i <= n; i++) new[names[i]] = 1 }
      { sym = $NF; sub(/@.*/, "", sym); file = substr($0, 1, index($0, ":") - 1)
        if ((sym in new) && !seen[file, sym]++) print file "\t" sym }')
fi

# 4: the packages asked for.
if [ -f "$bundle/packages.txt" ]; then
  while read -r package; do
    [ -z "$package" ] && continue
    grep -qxF "$package" <<< "$allowed_packages" ||
      finding "packages.txt asks for $package, which is not on target_packages.txt (only names checked to exist on both Debian 12 and Ubuntu 22.04 may be installed)"
  done < "$bundle/packages.txt"
else
  finding "no packages.txt in $bundle: rt-grade package writes it"
fi

echo "audit: ${#elfs[@]} programs and libraries, ${#objects[@]} objects and archives, $findings findings"
# Not a failing test as the last command: the ERR trap would call the audit itself broken.
[ "$findings" -eq 0 ] || exit 1
