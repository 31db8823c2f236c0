#!/usr/bin/env bash
# Gradescope's limits rehearsed (issue 28): the package's setup.sh and run_autograder on a fresh
# Debian 12 root (debootstrap), run_autograder under Gradescope's default limits (768 MB, half a
# CPU, 10 minutes) in a cgroup (v1), for the reference files and the starter stubs of each stage.
# Prints wall time, peak memory and score per stage and submission. setup.sh gets the grading's
# limits unless --setup-* says otherwise (Gradescope does not document the image build's). Needs
# root and takes minutes, so CTest has it only when configured with -DRT_REHEARSAL=ON.
#
#   sudo tools/gradescope_rehearsal.sh [--stages 1,6,10] [--together] [--fresh] [--check]
#        [--memory-mb 768] [--cpus 0.5] [--timeout 600] [--work /var/tmp/rt-rehearsal]
#        [--setup-memory-mb MB] [--setup-cpus N] [--setup-unlimited] [--isolation uid]
#        [--mirror URL] [--source TREE] [--rt-grade BIN]
set -euo pipefail

die() { echo "gradescope_rehearsal: error: $*" >&2; exit 2; }

src=$(cd "$(dirname "$0")/.." && pwd)
rt_grade=""
args="$*"
work=/var/tmp/rt-rehearsal
stages="" fresh=0 memory_mb=768 cpus=0.5 timeout_s=600 setup_limited=1 isolation="" check=0
setup_memory_mb="" setup_cpus="" together=0
mirror=""
while [ $# -gt 0 ]; do
  case $1 in
    --stages) stages=$2; shift 2 ;;
    --fresh) fresh=1; shift ;;
    --work) work=$2; shift 2 ;;
    --memory-mb) memory_mb=$2; shift 2 ;;
    --cpus) cpus=$2; shift 2 ;;
    --timeout) timeout_s=$2; shift 2 ;;
    --setup-unlimited) setup_limited=0; shift ;;
    --setup-memory-mb) setup_memory_mb=$2; shift 2 ;;  # setup.sh's own limits (default: the grading's)
    --setup-cpus) setup_cpus=$2; shift 2 ;;
    --isolation) isolation=$2; shift 2 ;;  # RT_GRADE_ISOLATION in the chroot (uid: Gradescope's mode)
    --mirror) mirror=$2; shift 2 ;;
    --source) src=$(cd "$2" && pwd); shift 2 ;;
    --rt-grade) rt_grade=$2; shift 2 ;;  # default: SOURCE/build/bin/rt-grade, built when missing
    --together) together=1; shift ;;  # also all the stages in one package (the default package)
    --check) check=1; shift ;;  # CTest: exit 1 unless every reference run fits and scores full marks
    -h|--help) sed -n '2,12p' "$0"; exit 0 ;;
    *) die "unknown option $1 (see --help)" ;;
  esac
done

# --- What the host must offer: each missing piece is one line naming the fix. ---
[ "$(id -u)" -eq 0 ] || die "must run as root (debootstrap, chroot, cgroups): sudo $0 $args"
command -v debootstrap > /dev/null || die "debootstrap is missing: apt-get install -y debootstrap"
for tool in chroot unzip jq timeout mount; do
  command -v $tool > /dev/null || die "$tool is missing: scripts/install-deps.sh installs it"
done
cg=/sys/fs/cgroup
[ -f $cg/memory/memory.limit_in_bytes ] ||
  die "no cgroup v1 memory controller at $cg/memory (boot with cgroup v1 or mount it: mount -t cgroup -o memory none $cg/memory)"
[ -f $cg/cpu/cpu.cfs_quota_us ] ||
  die "no cgroup v1 cpu controller at $cg/cpu (mount -t cgroup -o cpu,cpuacct none $cg/cpu)"
[ -f "$src/grader/cmd/batch.cpp" ] || die "$src is not the course tree: --source TREE"
setup_memory_mb=${setup_memory_mb:-$memory_mb} setup_cpus=${setup_cpus:-$cpus}
[[ $cpus =~ ^[0-9]+(\.[0-9]+)?$ && $setup_cpus =~ ^[0-9]+(\.[0-9]+)?$ && $memory_mb =~ ^[0-9]+$ &&
  $setup_memory_mb =~ ^[0-9]+$ && $timeout_s =~ ^[0-9]+$ ]] ||
  die "--cpus, --memory-mb, --setup-cpus, --setup-memory-mb and --timeout take numbers"

# The mirror apt already uses (a new machine is set up from the same one).
if [ -z "$mirror" ]; then
  mirror=$(grep -hoE '^(URIs:|deb) +http[^ ]+' /etc/apt/sources.list /etc/apt/sources.list.d/* 2>/dev/null |
    awk '{print $2}' | grep -v security | head -n1 || true)
  mirror=${mirror:-http://deb.debian.org/debian}
fi

root=$work/root
mkdir -p "$work"
exec 9> "$work/lock"
flock -n 9 || die "another rehearsal holds $work/lock: wait for it or pass --work DIR"

# --- Mounts and cgroups, undone on every exit. ---
mounted=()
cleanup() {
  for cgdir in "$cg/memory/rt-rehearsal" "$cg/cpu/rt-rehearsal"; do
    [ -d "$cgdir" ] || continue
    # Only the processes this script put in its own cgroup (a run the timeout left behind).
    for pid in $(cat "$cgdir/cgroup.procs" 2>/dev/null); do kill -9 "$pid" 2>/dev/null || true; done
  done
  sleep 1
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do umount -R "${mounted[i]}" 2>/dev/null || umount -lR "${mounted[i]}" || true; done
  rmdir "$cg/memory/rt-rehearsal" "$cg/cpu/rt-rehearsal" 2>/dev/null || true
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# --- A fresh Debian 12 root, kept between runs (--fresh rebuilds it). ---
if [ $fresh -eq 1 ] && [ -d "$root" ]; then
  grep -q " $root/" /proc/mounts && die "$root still has mounts (an interrupted run?): umount -R $root/{proc,sys,dev}"
  echo "removing $root"
  rm -rf --one-file-system "$root" "$work/setup.sum"
fi
if [ ! -f "$root/.rt-rehearsal-debootstrap" ]; then
  rm -rf --one-file-system "$root"
  echo "debootstrap bookworm from $mirror into $root (minbase: the least a new machine has)"
  debootstrap --variant=minbase bookworm "$root" "$mirror" > "$work/debootstrap.log" 2>&1 ||
    die "debootstrap failed (is $mirror reachable?): see $work/debootstrap.log"
  # The point releases a new machine gets too.
  printf 'deb %s bookworm main\ndeb %s bookworm-updates main\n' "$mirror" "$mirror" > "$root/etc/apt/sources.list"
  date -u +%FT%TZ > "$root/.rt-rehearsal-debootstrap"
fi
cp /etc/resolv.conf "$root/etc/resolv.conf"  # apt in setup.sh resolves the mirror's name
for fs in proc sys dev; do
  mkdir -p "$root/$fs"
  # Recursive binds made slaves, so unmounting them never reaches the host's /dev or /sys.
  mount --rbind "/$fs" "$root/$fs" && mount --make-rslave "$root/$fs"
  mounted+=("$root/$fs")
done

# --- The cgroup: memory (swap included when the kernel accounts it) and CPU quota. ---
mem=$cg/memory/rt-rehearsal cpu=$cg/cpu/rt-rehearsal
mkdir -p "$mem" "$cpu"
period=$(cat "$cpu/cpu.cfs_period_us")
# set_limits MB CPUS. Swap's limit is never below memory's: lift it first, whatever came before.
set_limits() {
  [ -f "$mem/memory.memsw.limit_in_bytes" ] && echo -1 > "$mem/memory.memsw.limit_in_bytes"
  echo $(($1 * 1024 * 1024)) > "$mem/memory.limit_in_bytes"
  [ -f "$mem/memory.memsw.limit_in_bytes" ] && echo $(($1 * 1024 * 1024)) > "$mem/memory.memsw.limit_in_bytes"
  awk -v p="$period" -v c="$2" 'BEGIN {printf "%d\n", p * c}' > "$cpu/cpu.cfs_quota_us"
}

oom_kills() { awk '/^oom_kill /{print $2}' "$mem/memory.oom_control"; }
# Runs "$@" inside the cgroup (limited) or outside it. Sets wall, peak_mb, rss_mb, oom, code.
# memory.max_usage_in_bytes counts page cache, which the kernel reclaims at the limit rather than
# kill; the sampled peak of rss + shmem (tmpfs, unreclaimable without swap) is what can kill.
run_measured() {
  local limited=$1 limit_s=$2; shift 2
  sync; echo 0 > "$mem/memory.force_empty" 2>/dev/null || true  # start without cached pages
  echo 0 > "$mem/memory.max_usage_in_bytes"
  local oom0; oom0=$(oom_kills)
  local start; start=$(date +%s.%N)
  if [ "$limited" -eq 1 ]; then
    bash -c 'echo $$ > "$1/cgroup.procs"; echo $$ > "$2/cgroup.procs"; shift 2; exec "$@"' \
      _ "$mem" "$cpu" timeout --kill-after=10 "$limit_s" "$@" &
  else
    bash -c 'echo $$ > "$1/cgroup.procs"; shift; exec "$@"' _ "$mem" "$@" &  # measured, not limited
  fi
  local pid=$! rss=0 now
  while kill -0 $pid 2>/dev/null; do
    now=$(awk '/^total_rss |^total_shmem /{s += $2} END {print s + 0}' "$mem/memory.stat")
    [ "$now" -gt "$rss" ] && rss=$now
    sleep 0.2
  done
  code=0; wait $pid || code=$?
  wall=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN {printf "%.0f", e - s}')
  peak_mb=$(( $(cat "$mem/memory.max_usage_in_bytes") / 1048576 ))
  rss_mb=$((rss / 1048576))
  oom=$(( $(oom_kills) - oom0 ))
}
# The machine Gradescope starts: a clean environment, root, the autograder's folder.
in_root=(chroot "$root" /usr/bin/env -i PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin
  HOME=/root LANG=C.UTF-8 TERM=dumb ${isolation:+RT_GRADE_ISOLATION=$isolation})

# --- The package, built by this tree's rt-grade. ---
if [ -n "$rt_grade" ]; then
  [ -x "$rt_grade" ] || die "--rt-grade $rt_grade is not an executable: cmake --build build --target rt-grade"
else
  rt_grade=$src/build/bin/rt-grade
fi
if [ ! -x "$rt_grade" ]; then
  echo "building rt-grade in $src/build"
  (cd "$src" && { [ -f build/CMakeCache.txt ] || cmake --preset release > /dev/null; } &&
    cmake --build build --target rt-grade > /dev/null) || die "rt-grade does not build: cmake --preset release && cmake --build build --target rt-grade"
fi
all=$(for d in "$src"/stages/[0-9][0-9]-*/; do [ -f "$d/grading.json" ] && basename "$d"; done)
[ -n "$all" ] || die "no stage with a grading.json in $src/stages"
stage_dir() { for d in $all; do [ $((10#${d%%-*})) -eq "$1" ] && { echo "$d"; return; }; done; return 1; }
if [ -z "$stages" ]; then stages=$(for d in $all; do echo $((10#${d%%-*})); done | paste -sd,); fi
for n in ${stages//,/ }; do stage_dir "$n" > /dev/null || die "stage $n has no grading.json"; done

"$rt_grade" package --source "$src" --out "$work/autograder.zip" > /dev/null
rm -rf "$work/unpacked" && mkdir -p "$work/unpacked" && (cd "$work/unpacked" && unzip -q "$work/autograder.zip")
sum=$(cd "$work/unpacked" && find . -type f -print0 | sort -z | xargs -0 sha256sum | sha256sum | cut -c1-16)
ag=$root/autograder
echo "Limits: memory ${memory_mb} MB, CPU $cpus, run_autograder timeout ${timeout_s} s; root $root; mirror $mirror"

# --- setup.sh, once per package content (the build is what takes long). ---
if [ "$(cat "$work/setup.sum" 2>/dev/null)" != "$sum" ]; then
  rm -rf "$ag" && mkdir -p "$ag" && cp -a "$work/unpacked/." "$ag/"
  # Gradescope does not say whether the image build has the grading limits: by default they apply.
  if [ $setup_limited -eq 1 ]; then
    set_limits "$setup_memory_mb" "$setup_cpus"
  else  # measured in the memory cgroup, so its limit is lifted
    [ -f "$mem/memory.memsw.limit_in_bytes" ] && echo -1 > "$mem/memory.memsw.limit_in_bytes"
    echo -1 > "$mem/memory.limit_in_bytes"
  fi
  echo "setup.sh: $( [ $setup_limited -eq 1 ] && echo "limited to $setup_memory_mb MB and CPU $setup_cpus (no timeout)" || echo "memory measured, not limited") ..."
  run_measured $setup_limited 0 "${in_root[@]}" bash /autograder/setup.sh > "$work/setup.log" 2>&1 < /dev/null
  echo "setup.sh: exit $code, ${wall} s wall, peak ${peak_mb} MB (cgroup, with cache), ${rss_mb} MB rss+shmem, OOM kills $oom"
  [ $code -eq 0 ] || die "setup.sh failed (exit $code): see $work/setup.log"
  limits="$setup_memory_mb MB, CPU $setup_cpus"; [ $setup_limited -eq 1 ] || limits="not limited"
  printf 'setup.sh\t%s\t%s\t%s\t%s\t%s\t-\t-\t-\n' "$limits" "$wall" "$peak_mb" "$rss_mb" "$oom" > "$work/setup.row"
  echo "$sum" > "$work/setup.sum"
else
  echo "setup.sh: reused (package unchanged since the last setup; --fresh redoes it)"
fi

# --- The starter stubs, as students get them. ---
rm -rf "$work/starter"
"$rt_grade" release --source "$src" --out "$work/starter" > /dev/null

# --- run_autograder per stage and submission, under the limits. ---
set_limits "$memory_mb" "$cpus"
rows=$work/rows.tsv
: > "$rows"
failed=0
# grade LABEL STAGES: one package for STAGES (an assignment), graded on the reference files and on
# the starter stubs of those stages, each run under the limits; one table row per run.
grade() {
  local label=$1 list=$2 who n dir from f res score max sandbox fits
  "$rt_grade" package --source "$src" --stages "$list" --out "$work/stage.zip" > /dev/null
  unzip -p "$work/stage.zip" run_autograder > "$ag/run_autograder" && chmod 755 "$ag/run_autograder"
  for who in reference starter; do
    rm -rf "$ag/submission" "$ag/results" && mkdir -p "$ag/submission" "$ag/results"
    # Gradescope unpacks the upload loose into submission/.
    for n in ${list//,/ }; do
      dir=$(stage_dir "$n")
      from=$src/stages/$dir; [ $who = starter ] && from=$work/starter/stages/$dir
      for f in $(jq -r '.student_files[]' "$src/stages/$dir/stage.json"); do cp "$from/$f" "$ag/submission/"; done
    done
    run_measured 1 "$timeout_s" "${in_root[@]}" /autograder/run_autograder > "$work/run-$label-$who.log" 2>&1 < /dev/null
    res=$ag/results/results.json score=- max=- sandbox=-
    if [ -s "$res" ]; then
      cp "$res" "$work/results-$label-$who.json"
      score=$(jq -r '.score' "$res")
      max=$(jq -r '[.tests[].max_score] | add' "$res")
      sandbox=$(jq -r '.output' "$res" | grep -oE 'Sandbox: (namespaces|uid drop|NONE)' | head -n1 | cut -c10- || true)
    fi
    fits=yes
    if [ $code -eq 124 ] || [ $code -eq 137 ]; then fits="no: timeout"
    elif [ "$oom" -gt 0 ]; then fits="no: OOM kill"
    elif [ $code -ne 0 ] || [ "$score" = - ]; then fits="no: exit $code"
    elif [ $who = reference ] &&
      awk -v s="$score" -v m="$max" 'BEGIN {exit !(s + 0 < m + 0)}'; then fits="no: not full marks"
    fi
    [ $who = reference ] && [ "$fits" != yes ] && failed=1
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s / %s\t%s\t%s\n' "$label" $who "$wall" "$peak_mb" "$rss_mb" "$oom" \
      "$score" "$max" "$fits" "${sandbox:--}" >> "$rows"
    echo "stages $list $who: ${wall} s, ${peak_mb} MB, $score / $max, $fits"
  done
}
for n in ${stages//,/ }; do grade "$(printf %02d "$n")" "$n"; done
# The default package grades every stage in one run_autograder: does the sum fit too?
[ $together -eq 0 ] || [ "${stages//[^,]/}" = "" ] || grade together "$stages"

echo
{
  printf 'stage\tsubmission\twall s\tpeak MB (cgroup)\trss+shmem MB\tOOM kills\tscore\tfits\tsandbox\n'
  [ -f "$work/setup.row" ] && cat "$work/setup.row"
  cat "$rows"
} | column -t -s $'\t'
echo "logs and results: $work (setup.log, run-NN-WHO.log, results-NN-WHO.json)"
[ $check -eq 0 ] || exit $failed
