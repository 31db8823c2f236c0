#!/usr/bin/env bash
# A platform's grading rehearsed (docs/grading.md, "What was rehearsed"): the package that
# `rt-grade package --platform P` writes, set up and run in a bare Debian 12 root (debootstrap
# --variant=minbase: none of this tree's packages) under the platform's limits, in a cgroup (v1):
#   gradescope    setup.sh and run_autograder at 768 MB and half a CPU (setup.sh too), 600 s
#   prairielearn  the image built from its Dockerfile (podman build --isolation=chroot on the
#                 bare root as debian:12), then the entry point at 2 GiB without swap, 0.9 CPU,
#                 1024 processes, no network (unshare -n), --timeout
#   autolab       make in Tango's layout on the same image, 899 s, output at most 1000 KiB
# Each graded stage runs on its reference files (full marks) and its starter stubs (0), and stage
# 01 on hostile files: network, fork bomb, disk flood, a forged results file. Prints wall time,
# peak memory and score per run. Needs root; minutes, so CTest has it only under the label
# `rehearsal` when configured with -DRT_REHEARSAL=ON.
#
#   sudo tools/rehearsal.sh --platform gradescope|prairielearn|autolab [--stages 1,9] [--check]
#        [--timeout S] [--work /var/tmp/rt-rehearsal] [--fresh] [--mirror URL] [--rt-grade BIN]
set -euo pipefail

die() { echo "rehearsal: error: $*" >&2; exit 2; }

src=$(cd "$(dirname "$0")/.." && pwd)
platform="" stages=1,9 check=0 timeout_s="" work=/var/tmp/rt-rehearsal fresh=0 mirror="" rt_grade=""
while [ $# -gt 0 ]; do
  case $1 in
    --platform) platform=$2; shift 2 ;;
    --stages) stages=$2; shift 2 ;;
    --check) check=1; shift ;;  # exit 1 unless every reference fits and scores full marks
    --timeout) timeout_s=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --fresh) fresh=1; shift ;;
    --mirror) mirror=$2; shift 2 ;;
    --rt-grade) rt_grade=$2; shift 2 ;;
    -h | --help) sed -n '2,17p' "$0"; exit 0 ;;
    *) die "unknown option $1 (see --help)" ;;
  esac
done
case $platform in
  gradescope) memory_mb=768 cpus=0.5 pids=0 swap=1 network=1 timeout_s=${timeout_s:-600} ;;
  prairielearn) memory_mb=2048 cpus=0.9 pids=1024 swap=0 network=0 timeout_s=${timeout_s:-600} ;;
  autolab) memory_mb=2048 cpus=1 pids=0 swap=1 network=1 timeout_s=${timeout_s:-899} ;;
  *) die "--platform gradescope, prairielearn or autolab" ;;
esac
[[ $stages =~ ^[0-9]+(,[0-9]+)*$ && $timeout_s =~ ^[0-9]+$ ]] || die "--stages takes 1,9 and --timeout seconds"

# --- What the host must offer: each missing piece is one line naming the fix. ---
[ "$(id -u)" -eq 0 ] || die "must run as root (debootstrap, chroot, cgroups)"
for tool in debootstrap chroot unzip jq timeout mount unshare; do
  command -v $tool > /dev/null || die "$tool is missing: apt-get install -y ${tool/chroot/coreutils}"
done
[ "$platform" = gradescope ] || command -v podman > /dev/null || die "podman is missing: apt-get install -y podman"
cg=/sys/fs/cgroup
for c in memory cpu pids; do
  [ -d $cg/$c ] || die "no cgroup v1 $c controller at $cg/$c (mount -t cgroup -o $c none $cg/$c)"
done
if [ -z "$rt_grade" ]; then rt_grade=$src/build/bin/rt-grade; fi
[ -x "$rt_grade" ] || die "$rt_grade is not built: cmake --build build --target rt-grade"
if [ -z "$mirror" ]; then
  mirror=$(grep -hoE '^(URIs:|deb) +http[^ ]+' /etc/apt/sources.list /etc/apt/sources.list.d/* 2> /dev/null |
    awk '{print $2}' | grep -v security | head -n1 || true)
  mirror=${mirror:-http://deb.debian.org/debian}
fi
mkdir -p "$work"
exec 9> "$work/lock"
flock -n 9 || die "another rehearsal holds $work/lock: wait for it or pass --work DIR"

# --- Mounts and cgroups, undone on every exit. ---
mounted=()
group=rt-rehearsal-$platform
cleanup() {
  for c in memory cpu pids; do
    for pid in $(cat "$cg/$c/$group/cgroup.procs" 2> /dev/null); do kill -9 "$pid" 2> /dev/null || true; done
  done
  sleep 1
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do umount -R "${mounted[i]}" 2> /dev/null || umount -lR "${mounted[i]}" || true; done
  for c in memory cpu pids; do rmdir "$cg/$c/$group" 2> /dev/null || true; done
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# --- The bare Debian 12 root, kept between runs (--fresh makes a new one). ---
bare=$work/root
if [ $fresh -eq 1 ]; then rm -rf --one-file-system "$bare"; fi
if [ ! -f "$bare/.rt-rehearsal-debootstrap" ]; then
  rm -rf --one-file-system "$bare"
  echo "debootstrap bookworm from $mirror into $bare (minbase: the least a new machine has)"
  debootstrap --variant=minbase bookworm "$bare" "$mirror" > "$work/debootstrap.log" 2>&1 ||
    die "debootstrap failed (is $mirror reachable?): see $work/debootstrap.log"
  printf 'deb %s bookworm main\ndeb %s bookworm-updates main\n' "$mirror" "$mirror" > "$bare/etc/apt/sources.list"
  date -u +%FT%TZ > "$bare/.rt-rehearsal-debootstrap"
fi
# enter ROOT: the system folders bound in (slaves: unmounting never reaches the host's).
enter() {
  cp /etc/resolv.conf "$1/etc/resolv.conf"
  for fs in proc sys dev; do
    mkdir -p "$1/$fs"
    mount --rbind "/$fs" "$1/$fs" && mount --make-rslave "$1/$fs"
    mounted+=("$1/$fs")
  done
}

# --- The cgroup and a measured run in it. ---
mem=$cg/memory/$group cpu=$cg/cpu/$group pid=$cg/pids/$group
mkdir -p "$mem" "$cpu" "$pid"
period=$(cat "$cpu/cpu.cfs_period_us")
[ -f "$mem/memory.memsw.limit_in_bytes" ] && memsw=1 || memsw=0
set_limits() {
  [ $memsw -eq 1 ] && echo -1 > "$mem/memory.memsw.limit_in_bytes"
  echo $((memory_mb * 1024 * 1024)) > "$mem/memory.limit_in_bytes"
  # Without swap: memory and swap together at the memory limit (when the kernel accounts swap).
  [ $memsw -eq 1 ] && [ $swap -eq 0 ] && echo $((memory_mb * 1024 * 1024)) > "$mem/memory.memsw.limit_in_bytes"
  awk -v p="$period" -v c="$cpus" 'BEGIN {printf "%d\n", p * c}' > "$cpu/cpu.cfs_quota_us"
  if [ "$pids" -gt 0 ]; then echo "$pids" > "$pid/pids.max"; else echo max > "$pid/pids.max"; fi
}
oom_kills() { awk '/^oom_kill /{print $2}' "$mem/memory.oom_control"; }
# run_measured LIMIT_S CMD...: sets wall, peak_mb (cgroup, page cache included), rss_mb (sampled
# rss + shmem: what can kill), oom, code.
run_measured() {
  local limit_s=$1; shift
  sync; echo 0 > "$mem/memory.force_empty" 2> /dev/null || true
  echo 0 > "$mem/memory.max_usage_in_bytes"
  local oom0 start now rss=0
  oom0=$(oom_kills) start=$(date +%s.%N)
  bash -c 'for g in "$1" "$2" "$3"; do echo $$ > "$g/cgroup.procs"; done; shift 3; exec "$@"' \
    _ "$mem" "$cpu" "$pid" timeout --kill-after=10 "$limit_s" "$@" &
  local child=$!
  while kill -0 $child 2> /dev/null; do
    now=$(awk '/^total_rss |^total_shmem /{s += $2} END {print s + 0}' "$mem/memory.stat")
    [ "$now" -gt "$rss" ] && rss=$now
    sleep 0.2
  done
  code=0; wait $child || code=$?
  wall=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN {printf "%.0f", e - s}')
  peak_mb=$(($(cat "$mem/memory.max_usage_in_bytes") / 1048576)) rss_mb=$((rss / 1048576))
  oom=$(($(oom_kills) - oom0))
}
# A clean environment, root, as the platforms start their jobs.
# Gradescope's and PrairieLearn's containers refuse new namespaces (Docker's seccomp profile): the
# grader's uid mode, as there. Autolab's Tango runs Docker too.
clean_env=(/usr/bin/env -i PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 TERM=dumb
  RT_GRADE_ISOLATION=uid)

# --- The package and the submissions. ---
stage_dir() { basename "$(echo "$src"/stages/"$(printf %02d "$1")"-*)"; }
for n in ${stages//,/ }; do [ -f "$src/stages/$(stage_dir "$n")/grading.json" ] || die "stage $n has no grading.json"; done
pkg=$work/$platform-package
rm -rf "$pkg" "$work/starter"
out=$pkg; [ "$platform" = gradescope ] && out=$work/autograder.zip
"$rt_grade" package --source "$src" --platform "$platform" --stages "$stages" --out "$out" > "$work/package.log" 2>&1 ||
  die "rt-grade package failed: see $work/package.log"
case $platform in
  gradescope) package_size=$(du -h "$out" | cut -f1) ;;
  prairielearn) package_size="$(du -sh "$pkg" | cut -f1) (image context)" ;;
  autolab) package_size="$(du -h "$pkg/autograde.tar" | cut -f1) (autograde.tar)" ;;
esac
"$rt_grade" release --source "$src" --out "$work/starter" > /dev/null
subs=$work/submissions
rm -rf "$subs" && mkdir -p "$subs"
# submission NAME: every graded stage's files, loose, from the reference or the starter tree.
for who in reference starter; do
  mkdir -p "$subs/$who"
  for n in ${stages//,/ }; do
    d=$(stage_dir "$n") from=$src/stages/$d
    [ $who = starter ] && from=$work/starter/stages/$d
    for f in $(jq -r '.student_files[]' "$src/stages/$d/stage.json"); do cp "$from/$f" "$subs/$who/"; done
  done
done
# Hostile stage 01 files: the reference with a static constructor that misbehaves.
hostile() {  # NAME C++...
  mkdir -p "$subs/$1" && cp "$subs/reference/"* "$subs/$1/" 2> /dev/null
  { cat "$src/stages/01-camera-rays/camera_rays.cpp"; echo "$2"; } > "$subs/$1/camera_rays.cpp"
}
hostile network '#include <arpa/inet.h>
#include <cstdio>
#include <sys/socket.h>
#include <unistd.h>
namespace { struct Net { Net() { int s = socket(AF_INET, SOCK_STREAM, 0); sockaddr_in a{}; a.sin_family = AF_INET; a.sin_port = htons(80);
  inet_pton(AF_INET, "151.101.2.132", &a.sin_addr); if (connect(s, (sockaddr*)&a, sizeof a) == 0) std::printf("NETWORK REACHED\n"); close(s); } } net; }'
hostile fork_bomb '#include <unistd.h>
namespace { struct Bomb { Bomb() { for (;;) fork(); } } bomb; }'
hostile disk_flood '#include <cstdio>
namespace { struct Flood { Flood() { static char block[1 << 20]; FILE* f = std::fopen("flood.bin", "wb");
  for (int i = 0; f && i < 100000; ++i) if (std::fwrite(block, 1, sizeof block, f) != sizeof block) break; } } flood; }'
hostile fake_results '#include <fstream>
namespace { struct Forger { Forger() { for (const char* p : {"/autograder/results/results.json", "/grade/results/results.json", "results.json"})
  std::ofstream(p) << R"({"score": 1000, "gradable": true, "tests": [{"name": "FAKE", "score": 1000, "max_score": 1}]})"; } } forger; }'

source "$src/grader/tests/stage_points.sh"
stage_max=$(for n in ${stages//,/ }; do stage_points "$n"; done | awk '{t += $1} END {print t}')

# --- The platform's machine: set up under its limits. ---
machine=$work/$platform-root
setup_row=""
if [ "$platform" = gradescope ]; then
  rm -rf --one-file-system "$machine" && cp -a "$bare" "$machine"
  enter "$machine"
  mkdir -p "$machine/autograder/source" && (cd "$machine/autograder/source" && unzip -q "$out")
  cp "$machine/autograder/source/run_autograder" "$machine/autograder/"
  set_limits
  run_measured 3600 chroot "$machine" "${clean_env[@]}" bash /autograder/source/setup.sh > "$work/setup.log" 2>&1 < /dev/null
  [ $code -eq 0 ] || die "setup.sh failed (exit $code): see $work/setup.log"
  setup_row="setup.sh ($memory_mb MB, CPU $cpus)\t$wall\t$peak_mb\t$rss_mb\t$oom\t-"
else
  # The image: the Dockerfile built by podman on the bare root (imported as debian:12), with
  # chroot isolation (no container runtime needed), then its file system exported.
  base=localhost/rt-rehearsal-debian12
  podman image exists "$base" 2> /dev/null && [ "$(cat "$work/base.sum" 2> /dev/null)" = "$(cat "$bare/.rt-rehearsal-debootstrap")" ] ||
    { tar -C "$bare" -c . | podman import - "$base" > /dev/null && cat "$bare/.rt-rehearsal-debootstrap" > "$work/base.sum"; }
  image_context=$pkg
  if [ "$platform" = autolab ]; then  # Autolab's image is the course's: the same Debian 12 one
    image_context=$work/autolab-image && rm -rf "$image_context"
    "$rt_grade" package --source "$src" --platform prairielearn --stages "$stages" --out "$image_context" > /dev/null 2>&1 ||
      die "rt-grade package (the image) failed"
  fi
  # Measured under the platform's limits (the course builds it where it likes: an upper bound).
  set_limits
  run_measured 3600 podman build --isolation=chroot --from "$base" -t "localhost/rt-grade-$platform" "$image_context" > "$work/image.log" 2>&1
  [ $code -eq 0 ] || die "podman build failed (exit $code): see $work/image.log"
  image_mb=$(podman image inspect --format '{{.Size}}' "localhost/rt-grade-$platform" | awk '{printf "%.0f", $1 / 1e6}')
  setup_row="image build ($memory_mb MB, CPU $cpus; image $image_mb MB)\t$wall\t$peak_mb\t$rss_mb\t$oom\t-"
  rm -rf --one-file-system "$machine" && mkdir -p "$machine"
  container=$(podman create "localhost/rt-grade-$platform")
  podman export "$container" | tar -C "$machine" -x
  podman rm "$container" > /dev/null
  enter "$machine"
  set_limits
fi

# --- Each submission graded as the platform runs it. ---
rows=$work/$platform-rows.tsv
: > "$rows"
failed=0
grade() {  # NAME: sets score, max and fits; appends a row
  local name=$1 res="" log=$work/$platform-$1.log extra=""
  case $platform in
    gradescope)
      rm -rf "$machine/autograder/submission" "$machine/autograder/results"
      mkdir -p "$machine/autograder/submission" && cp "$subs/$name/"* "$machine/autograder/submission/"
      run_measured "$timeout_s" chroot "$machine" "${clean_env[@]}" /autograder/run_autograder > "$log" 2>&1 < /dev/null
      res=$machine/autograder/results/results.json
      score=$(jq -r '.score' "$res" 2> /dev/null || echo -) max=$(jq -r '[.tests[].max_score] | add' "$res" 2> /dev/null || echo -) ;;
    prairielearn)
      rm -rf "$machine/grade" && mkdir -p "$machine/grade/student" "$machine/grade/results" "$machine/grade/data"
      cp "$subs/$name/"* "$machine/grade/student/"
      echo '{"params": {}}' > "$machine/grade/data/data.json"
      run_measured "$timeout_s" unshare -n chroot "$machine" "${clean_env[@]}" /grader/entrypoint.sh > "$log" 2>&1 < /dev/null
      res=$machine/grade/results/results.json
      score=$(jq -r 'if .gradable then .score else "not gradable" end' "$res" 2> /dev/null || echo -) max=1
      extra="results.json $(stat -c %s "$res" 2> /dev/null || echo -) bytes" ;;
    autolab)
      local job=$machine/home/autograde/autolab
      rm -rf "$job" && mkdir -p "$job"
      cp "$pkg/autograde-Makefile" "$job/Makefile" && cp "$pkg/autograde.tar" "$job/"
      (cd "$subs/$name" && zip -q -r "$job/handin.zip" .)
      run_measured "$timeout_s" chroot "$machine" "${clean_env[@]}" bash -c 'cd /home/autograde/autolab && make -s 2>&1' > "$log" 2>&1 < /dev/null
      score=$(tail -n 1 "$log" | jq -r '.scoreboard[0]' 2> /dev/null || echo -) max=$stage_max
      extra="output $(($(stat -c %s "$log") / 1024)) KiB, last line JSON: $(tail -n 1 "$log" | jq -e . > /dev/null 2>&1 && echo yes || echo no)" ;;
  esac
  [ -n "${res:-}" ] && cp "$res" "$work/$platform-$name.json" 2> /dev/null
  fits=yes
  if [ $code -eq 124 ] || [ $code -eq 137 ]; then fits="no: timeout"
  elif [ "$oom" -gt 0 ]; then fits="no: OOM kill"
  elif [ $code -ne 0 ]; then fits="no: exit $code"
  fi
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$name" "$wall" "$peak_mb" "$rss_mb" "$oom" "$score${max:+ / $max}" "$fits${extra:+; $extra}" >> "$rows"
  echo "$platform $name: ${wall} s, ${peak_mb} MB, score $score${max:+ / $max}, $fits${extra:+; $extra}"
}
for name in reference starter network fork_bomb disk_flood fake_results; do grade "$name"; done
# The reference's full marks: Gradescope's and Autolab's maximum, PrairieLearn's 1.
ref_ok=$(awk -F'\t' '$1 == "reference" && $7 ~ /^yes/ {print "yes"}' "$rows")
ref_score=$(awk -F'\t' '$1 == "reference" {print $6}' "$rows")
case $platform in
  prairielearn) [[ $ref_score == "1 / 1" ]] || ref_ok=no ;;
  *) awk -v s="$ref_score" 'BEGIN {split(s, a, " / "); exit !(a[1] == a[2])}' || ref_ok=no ;;
esac
[ "$ref_ok" = yes ] || failed=1
grep -q "NETWORK REACHED" "$work/$platform-network.log" "$machine"/*/results/results.json 2> /dev/null && failed=1

echo
echo "$platform, stages $stages: package $package_size; limits ${memory_mb} MB$([ $swap -eq 0 ] && echo ' without swap'), CPU $cpus$([ "$pids" -gt 0 ] && echo ", $pids processes")$([ $network -eq 0 ] && echo ', no network'), ${timeout_s} s"
{
  printf 'run\twall s\tpeak MB (cgroup)\trss+shmem MB\tOOM kills\tscore\tfits\n'
  [ -n "$setup_row" ] && printf "$setup_row\n"
  cat "$rows"
} | column -t -s $'\t'
echo "logs: $work/$platform-*.log"
[ $check -eq 0 ] || exit $failed
