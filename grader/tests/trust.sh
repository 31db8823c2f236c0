#!/usr/bin/env bash
# The grader's trust (docs/grading.md, "What the sandbox guarantees"): one case per class of
# attack, each built from the instructor's files so it follows the course, plus the benign
# corpus of ordinary C++ that must always score full marks.
#   trust.sh BIN_DIR SRC_DIR CASE
set -uo pipefail
bin=$1 src=$2 case=$3
source "$(dirname "$0")/case_lib.sh"
cache=${RT_GRADE_CACHE:-$src/build/grader-cache}
hidden_marker="Hidden stage 02 tests"  # the first line of stages/02-intersections/hidden/hidden_test.cpp
grep -q "$hidden_marker" "$src/$s2/hidden/hidden_test.cpp" || { echo "FAIL: hidden test marker changed"; exit 1; }
stages=1 limit=(--time-limit 5) checks=()

# A forger that tries every way to turn its FAIL into a PASS: read the records back from any
# descriptor (read, recv, /proc/self/fd reopen) and rewrite them, take the nonce from what it
# read or from hex strings in its memory, write PASS records with every guess, exit 0.
forger() {
  cat <<'CPP'
#include <fcntl.h>
#include <csignal>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>
namespace {
void forge() {
  std::ifstream cmd("/proc/self/cmdline", std::ios::binary);
  std::string all((std::istreambuf_iterator<char>(cmd)), std::istreambuf_iterator<char>()), test;
  for (std::size_t p = 0, q; p < all.size(); p = q + 1) {
    q = all.find('\0', p); if (q == std::string::npos) q = all.size();
    const std::string a = all.substr(p, q - p);
    if (a.rfind("--gtest_filter=", 0) == 0) test = a.substr(15);
  }
  std::vector<std::string> nonces{std::string(32, '0')};
  auto harvest = [&](const std::string& data) {
    for (std::size_t at = 0; (at = data.find("RTG1 ", at)) != std::string::npos; at += 5)
      if (at + 37 <= data.size()) nonces.push_back(data.substr(at + 5, 32));
  };
  char buf[65536];
  for (int fd = 3; fd < 64; ++fd) {
    ssize_t n = recv(fd, buf, sizeof buf, MSG_DONTWAIT); if (n > 0) harvest(std::string(buf, n));
    n = pread(fd, buf, sizeof buf, 0); if (n > 0) harvest(std::string(buf, n));
    const std::string path = "/proc/self/fd/" + std::to_string(fd);
    const int again = open(path.c_str(), O_RDONLY | O_NONBLOCK);
    if (again >= 0) { n = read(again, buf, sizeof buf); if (n > 0) harvest(std::string(buf, n)); close(again); }
  }
  // Pairs of 32-byte arrays side by side whose XOR is 32 hex digits (a masked nonce and its mask).
  auto xor_pairs = [&](const unsigned char* m, unsigned long size) {
    for (unsigned long i = 0; i + 64 <= size && nonces.size() < 64; ++i) {
      int k = 0;
      for (; k < 32; ++k) { const int c = m[i + k] ^ m[i + 32 + k]; if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) break; }
      if (k == 32) { std::string n(32, '0'); for (k = 0; k < 32; ++k) n[k] = char(m[i + k] ^ m[i + 32 + k]); nonces.push_back(n); }
    }
  };
  std::ifstream maps("/proc/self/maps"); std::string line;
  while (std::getline(maps, line) && nonces.size() < 64) {
    unsigned long lo = 0, hi = 0; char perms[8] = {};
    if (std::sscanf(line.c_str(), "%lx-%lx %7s", &lo, &hi, perms) != 3 || perms[1] != 'w') continue;
    if (hi - lo > (8ul << 20)) continue;
    const char* m = reinterpret_cast<const char*>(lo); int run = 0;
    xor_pairs(reinterpret_cast<const unsigned char*>(lo), hi - lo);
    for (unsigned long i = 0; i < hi - lo && nonces.size() < 64; ++i) {
      const char c = m[i];
      run = ((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f')) ? run + 1 : 0;
      if (run == 32) nonces.push_back(std::string(m + i - 31, 32));
    }
  }
  for (int fd = 3; fd < 64; ++fd)
    for (const auto& n : nonces) {
      const std::string rec = "RTG1 " + n + " PASS " + test + "\nRTG1 " + n + " END 1 0\n";
      if (write(fd, rec.data(), rec.size()) < 0) break;
    }
  std::printf("FORGER ran: %zu nonce guesses\n", nonces.size()); std::fflush(stdout);
  _exit(0);
}
// Overwrites the writable data of its own program (where a test framework in the process would
// keep its results) with 1s, so every flag reads true and every counter is odd, then forges.
void corrupt_and_forge() {
  std::printf("CORRUPTER ran\n"); std::fflush(stdout);
  std::ifstream maps("/proc/self/maps"); std::string line, exe;
  std::getline(std::ifstream("/proc/self/cmdline"), exe, '\0');
  while (std::getline(maps, line)) {
    unsigned long lo = 0, hi = 0; char perms[8] = {};
    if (std::sscanf(line.c_str(), "%lx-%lx %7s", &lo, &hi, perms) != 3 || perms[1] != 'w') continue;
    if (line.find(exe.substr(exe.rfind('/') + 1)) == std::string::npos) continue;
    std::memset(reinterpret_cast<void*>(lo), 1, hi - lo);
  }
  forge();
}
}
CPP
}

# A C++ base64 decoder and a writer of an embedded image to the renderer's -o path.
hand_in() {  # hand_in SCENE...: the shipped references of those scenes, embedded
  echo '#include <cstdio>'; echo '#include <fstream>'; echo '#include <iterator>'
  echo '#include <string>'; echo '#include <unistd.h>'
  echo 'namespace { const char* kImages[][2] = {'
  for scene in "$@"; do
    oiiotool "$src/reference_images/01-camera-rays/$scene.png" --colorconvert sRGB linear -d half \
      --compression zip -o "$work/$scene.exr" || exit 1
    printf '{"%s", "%s"},\n' "$scene" "$(base64 -w0 "$work/$scene.exr")"
  done
  cat <<'CPP'
};
std::string decode(const char* in) {
  static const std::string abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out; int bits = 0, value = 0;
  for (; *in && *in != '='; ++in) { value = value * 64 + int(abc.find(*in)); bits += 6;
    if (bits >= 8) { bits -= 8; out.push_back(char((value >> bits) & 255)); } }
  return out;
}
struct HandIn { HandIn() {
  std::ifstream cmd("/proc/self/cmdline", std::ios::binary);
  std::string all((std::istreambuf_iterator<char>(cmd)), std::istreambuf_iterator<char>());
  std::string out, scene;
  for (std::size_t p = 0, q; p < all.size(); p = q + 1) {
    q = all.find('\0', p); if (q == std::string::npos) q = all.size();
    const std::string a = all.substr(p, q - p);
    if (a.size() > 5 && a.substr(a.size() - 5) == ".json") scene = a.substr(a.rfind('/') + 1, a.size() - a.rfind('/') - 6);
    if (!out.empty() && out == "-o") out = a;
    if (a == "-o") out = "-o";
  }
  for (const auto& img : kImages)
    if (scene == img[0]) { std::ofstream(out, std::ios::binary) << decode(img[1]); _exit(0); }
} } hand_in; }
CPP
}

# Honest C++ that ordinary students write: every construct GCC emits unusual symbols for.
benign_helpers() {
  cat <<'CPP'
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <typeinfo>
#include <vector>
int g_calls = 0;                       // a global variable (an unmangled C name)
inline int g_inline_counter = 0;       // an inline variable (a unique global)
extern "C" int student_c_helper(int x) { return x + 1; }  // an extern "C" helper
namespace helpers {
struct Shape { virtual ~Shape() = default; virtual double area() const = 0; };  // vtable, RTTI
struct Square : Shape { double s = 2; double area() const override { return s * s; } };
template <typename T> T twice(T x) { return x + x; }                           // templates
std::string describe(int n) { return "n=" + std::to_string(n); }               // to_string's table
int safe_parse(const std::string& text) {                                      // exceptions by reference
  try { if (text.empty()) throw std::invalid_argument("empty"); return std::stoi(text); }
  catch (const std::exception& e) { return -1; }
}
int next_id() { static int id = 0; return ++id; }                              // a static local
thread_local int t_scratch = 0;                                                // TLS
std::map<std::string, std::function<int(int)>> table() {                       // std::function
  return {{"inc", [](int x) { return x + 1; }}, {"dbl", twice<int>}};
}
const char* kind(const Shape& s) { return dynamic_cast<const Square*>(&s) ? typeid(s).name() : "?"; }
struct Logger { std::ostringstream out; Logger() { out << "ready"; } } g_logger;  // a constructor
int use_everything() {
  std::unique_ptr<Shape> sq = std::make_unique<Square>();
  g_calls += twice(1) + next_id() + student_c_helper(1) + safe_parse("") + g_inline_counter++;
  t_scratch = int(sq->area()) + int(describe(3).size()) + table()["inc"](1);
  if (std::getenv("RT_BENIGN_NOISE")) std::cerr << kind(*sq) << g_logger.out.str() << "\n";
  return g_calls + t_scratch;
}
}  // namespace helpers
CPP
}

case $case in
  forge_destructor | forge_atexit | forge_signal | forge_midtest | forge_thread | forge_corrupt)
    stub "$src/$s1/camera_rays.cpp" > "$sub/$s1/camera_rays.cpp"
    forger | append1
    case $case in
      forge_destructor) echo 'namespace { struct Late { ~Late() { forge(); } } late; }' | append1 ;;
      forge_atexit) echo 'namespace { struct Reg { Reg() { std::atexit([] { forge(); }); } } reg; }' | append1 ;;
      # A timer fires in the middle of the test: the forger runs before the runner's record.
      forge_signal) echo 'namespace { struct Arm { Arm() { std::signal(SIGALRM, [](int) { forge(); });
        itimerval t{}; t.it_value.tv_usec = 20000; setitimer(ITIMER_REAL, &t, nullptr); } } arm; }' | append1
        # ... and the test body must still be running when it fires.
        sed -i 's|RT_NOT_IMPLEMENTED("stages/01-camera-rays/README.md#perspective-rays");|{ volatile long spin = 0; while (spin < 300000000L) spin = spin + 1; } RT_NOT_IMPLEMENTED("stages/01-camera-rays/README.md#perspective-rays");|' "$sub/$s1/camera_rays.cpp" ;;
      # The first call of the student's function, inside the test: well-formed records on every
      # descriptor, then exit 0 before the test's assertions run.
      forge_midtest)
        sed -i 's|RT_NOT_IMPLEMENTED("stages/01-camera-rays/README.md#perspective-rays");|forge_now(); RT_NOT_IMPLEMENTED("stages/01-camera-rays/README.md#perspective-rays");|' "$sub/$s1/camera_rays.cpp"
        sed -i '0,/^namespace rt {/s//void forge_now();\nnamespace rt {/' "$sub/$s1/camera_rays.cpp"
        echo 'void forge_now() { forge(); }' | append1 ;;
      # The first call corrupts the process's state (its program's writable data), then forges.
      forge_corrupt)
        sed -i 's|RT_NOT_IMPLEMENTED("stages/01-camera-rays/README.md#perspective-rays");|corrupt_now(); RT_NOT_IMPLEMENTED("stages/01-camera-rays/README.md#perspective-rays");|' "$sub/$s1/camera_rays.cpp"
        sed -i '0,/^namespace rt {/s//void corrupt_now();\nnamespace rt {/' "$sub/$s1/camera_rays.cpp"
        echo 'void corrupt_now() { corrupt_and_forge(); }' | append1 ;;
      # A second thread forges while the test runs.
      forge_thread) echo '#include <thread>
namespace { struct Start { Start() { std::thread([] { usleep(20000); forge(); }).detach(); } } start; }' | append1
        sed -i 's|RT_NOT_IMPLEMENTED("stages/01-camera-rays/README.md#perspective-rays");|{ volatile long spin = 0; while (spin < 300000000L) spin = spin + 1; } RT_NOT_IMPLEMENTED("stages/01-camera-rays/README.md#perspective-rays");|' "$sub/$s1/camera_rays.cpp" ;;
    esac
    # The forger runs in the worker, which holds no verdict channel, no nonce and no GoogleTest:
    # every test scores what the stubs score.
    checks=(--score-max 0 --contains "FORGER ran")
    # What corruption leaves of the forger itself may not run to its end: the report says it began.
    [ $case != forge_corrupt ] || checks=(--score-max 0 --contains "CORRUPTER ran") ;;
  hand_in_reference)  # the shipped references written as renders: the shipped view passes...
    stub "$src/$s1/camera_rays.cpp" > "$sub/$s1/camera_rays.cpp"
    hand_in perspective_directions orthographic_directions | append1
    # ... but the unseen view of the same scene exposes it: no point for either scene.
    checks=(--score-max 0 --contains "0.000% of the pixels differ"
            --contains "the image is one of the shipped reference images") ;;
  compile_reads)  # the compiler is made to read files: hidden tests, /etc/shadow, /etc/passwd
    hidden=$cache/workspace/src/$s2/hidden/hidden_test.cpp
    shadow_line=$(head -1 /etc/shadow 2>/dev/null | cut -d: -f1-2)
    passwd_line=$(head -1 /etc/passwd)
    tricks=("%:include \"$hidden\""
            "#line 1 \"$hidden\"
int broken = ;"
            "asm(\".inc\" \"bin \\\"/etc/shadow\\\"\");"
            "#/**/include \"/etc/passwd\""
            "#line 1 \"/etc/shadow\"
int broken = ;")
    stages=2 failed=0
    for trick in "${tricks[@]}"; do
      rm -rf "$sub"; mkdir -p "$sub/$s2"; solution2; printf '%s\n' "$trick" | append2
      checks=(--score-max 0 --not-contains "$hidden_marker" --not-contains "$passwd_line")
      [ -n "$shadow_line" ] && checks+=(--not-contains "$shadow_line")
      echo "--- trick: $trick"
      grade_and_check || failed=1
      grep -q "$hidden_marker" "$work/report.html" && { echo "FAIL: hidden test text in the report"; failed=1; }
    done
    exit $failed ;;
  benign_mix)  # stage 01 with every unusual construct
    solution1; benign_helpers | append1
    checks=(--full-marks --not-contains "Build (compiling your files)") ;;
  benign_exceptions)  # the reference plus a helper that catches std::exception by reference
    # Stage 02's own limits: its CGAL leak test needs about 5 s of CPU through the judge on a slow
    # machine, and honest code must score full marks under the limits students get.
    solution2; stages=2 limit=()
    echo '#include <stdexcept>
namespace rt { int checked(int x) { try { if (x < 0) throw std::runtime_error("negative"); return x; }
  catch (const std::exception& e) { return 0; } } }' | append2
    checks=(--full-marks --not-contains "Build (compiling your files)") ;;
  benign_to_string)  # the reference plus std::to_string(int) (GCC 12: a unique global digit table)
    solution2; stages=2 limit=()  # stage 02's own limits (benign_exceptions says why)
    echo '#include <string>
namespace rt { std::string label(int i) { return "primitive " + std::to_string(i); } }' | append2
    checks=(--full-marks --not-contains "Build (compiling your files)") ;;
  overrides_refused)  # what would replace trusted code is still refused, with a clear message
    failed=0
    for extra in 'int main() { return 0; }' \
                 'namespace testing { namespace internal { bool ParseInt32(const char*, const char*, int*) { return true; } } }' \
                 '#include "testing/stage_test.h"
void rt::testing::StageTest::TearDown() {}' \
                 '#include "render/render.h"
namespace rt { int resolve_thread_count(int) { return 1; } }'; do
      rm -rf "$sub"; mkdir -p "$sub/$s1"; solution1; printf '%s\n' "$extra" | append1
      checks=(--score-max 0 --contains "Build (compiling your files)" --contains "Remove them")
      echo "--- override: $extra"
      grade_and_check || failed=1
    done
    exit $failed ;;
  together_reference)  # stages graded together score as when graded alone; stage 06's
    # leaderboard ranks by the traversal cost, also in the container mode (TrustContainer),
    # where the reference reads the student's tree through permissions, not a bind mount
    rm -rf "$sub"; mkdir -p "$sub"
    cp "$src/$s2/intersections.cpp" "$src/stages/06-bvh/bvh.cpp" "$sub/"
    stages=2,6 limit=()
    checks=(--full-marks --full-marks-tag stage02 --full-marks-tag stage06
            --leaderboard-first "Traversal cost per ray") ;;
  together_broken)  # a stage 02 stub does not cost stage 06 anything
    rm -rf "$sub"; mkdir -p "$sub"
    stub "$src/$s2/intersections.cpp" > "$sub/intersections.cpp"
    cp "$src/stages/06-bvh/bvh.cpp" "$sub/"
    stages=2,6 limit=()
    checks=(--full-marks-tag stage06) ;;
  host_writes)  # the shared /tmp, /var/tmp, /dev/shm and the grader's folders stay untouched
    tag=rt-grade-canary-$$
    solution1
    sed "s|@TAG@|$tag|" <<'CPP' | append1
#include <fstream>
#include <unistd.h>
namespace { struct Litter { Litter() {
  for (const char* dir : {"/tmp", "/var/tmp", "/dev/shm"}) std::ofstream(std::string(dir) + "/@TAG@") << "x";
  std::ofstream("/tmp/results.json") << "{}";
} } litter; }
CPP
    checks=(--full-marks)
    [ -e /tmp/results.json ] && had_results=1 || had_results=0  # someone else's: not ours to judge
    grade_and_check; failed=$?
    for f in /tmp/$tag /var/tmp/$tag /dev/shm/$tag; do
      [ -e "$f" ] && { echo "FAIL: the sandbox wrote $f on the host"; rm -f "$f"; failed=1; }
    done
    if [ $had_results = 0 ] && [ -e /tmp/results.json ]; then
      echo "FAIL: the sandbox wrote /tmp/results.json on the host"; rm -f /tmp/results.json; failed=1
    fi
    exit $failed ;;
  network)  # a test that resolves a name and connects to a listener on 127.0.0.1 (TCP and UDP)
    # The listener: perl-base is in every Debian and Ubuntu system. It logs what reaches it.
    perl -MIO::Socket::INET -MIO::Select -e '
      my $t = IO::Socket::INET->new(LocalAddr => "127.0.0.1", LocalPort => 0, Listen => 16) or die;
      my $u = IO::Socket::INET->new(LocalAddr => "127.0.0.1", LocalPort => 0, Proto => "udp") or die;
      open(my $p, ">", "$ARGV[0].tmp") or die; print $p $t->sockport, " ", $u->sockport, "\n";
      close $p; rename("$ARGV[0].tmp", $ARGV[0]); $| = 1;
      my $s = IO::Select->new($t, $u);
      for (;;) { for my $h ($s->can_read) {
        if ($h == $t) { my $c = $t->accept; print "tcp\n"; close $c if $c }
        else { my $d; $u->recv($d, 512); print "udp\n" } } }' "$work/ports" >> "$work/seen" &
    listener=$!
    for _ in $(seq 100); do [ -s "$work/ports" ] && break; sleep 0.1; done
    read -r tcp udp < "$work/ports" || { echo "FAIL: no listener"; kill $listener; exit 1; }
    # The listener works: a connection from here is seen.
    (exec 3<> "/dev/tcp/127.0.0.1/$tcp") && sleep 0.5
    [ "$(cat "$work/seen")" = tcp ] || { echo "FAIL: the listener saw nothing from the host"; kill $listener; exit 1; }
    : > "$work/seen"
    solution1
    sed "s|@TCP@|$tcp|g; s|@UDP@|$udp|g" <<'CPP' | append1
#include <arpa/inet.h>
#include <netdb.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>
namespace { struct Phone { Phone() {
  addrinfo hints{}, *found = nullptr;
  hints.ai_family = AF_INET; hints.ai_socktype = SOCK_STREAM;
  if (getaddrinfo("localhost", "@TCP@", &hints, &found) == 0) {  // a name, resolved
    for (addrinfo* a = found; a; a = a->ai_next) {
      const int s = socket(a->ai_family, a->ai_socktype, 0);
      if (s >= 0) { (void)!connect(s, a->ai_addr, a->ai_addrlen); close(s); } }
    freeaddrinfo(found);
  }
  sockaddr_in to{}; to.sin_family = AF_INET; to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  to.sin_port = htons(@TCP@);
  int s = socket(AF_INET, SOCK_STREAM, 0);
  if (s >= 0) { (void)!connect(s, reinterpret_cast<sockaddr*>(&to), sizeof to); close(s); }
  to.sin_port = htons(@UDP@);
  s = socket(AF_INET, SOCK_DGRAM, 0);
  if (s >= 0) { (void)!sendto(s, "x", 1, 0, reinterpret_cast<sockaddr*>(&to), sizeof to); close(s); }
} } phone; }
CPP
    checks=(--full-marks)
    grade_and_check; failed=$?
    sleep 0.5
    kill $listener
    if [ -s "$work/seen" ]; then
      echo "FAIL: the listener saw $(sort "$work/seen" | uniq -c | tr '\n' ' ')from the sandbox"; failed=1
    fi
    exit $failed ;;
  symlink_plant)  # symlinks where the grader reads and writes: it never follows them
    echo original > "$work/canary"
    solution1
    sed "s|@CANARY@|$work/canary|" <<'CPP' | append1
#include <unistd.h>
#include <fstream>
#include <iterator>
#include <string>
namespace { struct Plant { Plant() {
  std::ifstream cmd("/proc/self/cmdline", std::ios::binary);
  std::string all((std::istreambuf_iterator<char>(cmd)), std::istreambuf_iterator<char>());
  for (const char* name : {"render.exr", "student.png", "reference.png", "diff.png", "results.json",
                           "../render.exr", "../trusted", "../png", "../capture"})
    (void)!symlink("@CANARY@", name);
  if (all.find("render") != std::string::npos) _exit(0);  // the "image" is the symlink
} } plant; }
CPP
    checks=(--score-max 10 --contains "the renderer wrote no image")
    grade_and_check || exit 1
    [ "$(cat "$work/canary")" = original ] || { echo "FAIL: the canary was changed through a symlink"; exit 1; }
    exit 0 ;;
  daemon | uid_daemon)  # setsid + double fork: the grandchild must not outlive its test
    [ $case = uid_daemon ] && export RT_GRADE_ISOLATION=uid
    marker=rtgd$$
    solution1
    sed "s|@MARKER@|$marker|" <<'CPP' | append1
#include <sys/prctl.h>
#include <unistd.h>
namespace { struct Daemon { Daemon() {
  if (fork() == 0) { setsid(); if (fork() == 0) { prctl(PR_SET_NAME, "@MARKER@"); for (;;) sleep(1); } _exit(0); }
} } daemon_; }
CPP
    checks=(--full-marks)
    grade_and_check || exit 1
    sleep 1
    # Zombies are dead (killed, not yet reaped by whoever adopted them): only live ones count.
    if ps -eo stat=,comm= | awk -v m="$marker" '$2 == m && $1 !~ /^Z/ {found=1} END {exit !found}'; then
      echo "FAIL: a daemon outlived its test"; pkill -9 -x "$marker"; exit 1
    fi
    exit 0 ;;
  batch_fork_bomb)  # a fork bomb graded beside an honest submission costs it nothing, four times (its limits are CPU time: load cannot cost it a point)
    mkdir -p "$work/all/honest/$s1" "$work/all/bomb/$s1"
    cp "$src/$s1/camera_rays.cpp" "$work/all/honest/$s1/"
    cp "$src/$s1/camera_rays.cpp" "$work/all/bomb/$s1/"
    cat >> "$work/all/bomb/$s1/camera_rays.cpp" <<'CPP'
#include <unistd.h>
namespace { struct Bomb { Bomb() { while (fork() >= 0) {} usleep(300000); _exit(1); } } bomb; }
CPP
    for round in 1 2 3 4; do
      rm -rf "$work/grades"
      "$bin/rt-grade" batch "$work/all" --out "$work/grades" --jobs 2 --stages 1 --time-limit 5 || exit 1
      expect_row honest max "$work/grades/scores.csv" ||
        { echo "FAIL: round $round:"; cat "$work/grades/scores.csv"; "$bin/results_check" "$work/grades/honest/results.json" --full-marks; exit 1; }
      expect_row bomb 0 "$work/grades/scores.csv" || { echo "FAIL: round $round: the bomb scored"; exit 1; }
      echo "round $round: honest full marks, bomb 0"
    done
    exit 0 ;;
  concurrent)  # the grader's own cases pass while another grading (a fork bomb) runs beside them
    mkdir -p "$work/bomb/$s1"
    cp "$src/$s1/camera_rays.cpp" "$work/bomb/$s1/"
    echo '#include <unistd.h>
namespace { struct Bomb { Bomb() { for (;;) fork(); } } bomb; }' >> "$work/bomb/$s1/camera_rays.cpp"
    # The bomb grades at the lowest priority: it still forks to its limits and is reaped beside
    # the cases below (same sandbox uid pool, same machine), but its spinning (a CPU budget of 3 s
    # per run, run after run) takes only CPU nothing else wants, not half of a CI run's.
    ( while [ ! -e "$work/stop" ]; do
        nice -n 19 "$bin/rt-grade" "$work/bomb" --stages 1 --time-limit 3 --quiet \
          --results "$work/bomb.json" > /dev/null 2>&1 &
        echo $! > "$work/bomb.pid"
        wait $!
      done ) &
    background=$!
    sleep 3
    failed=0
    for c in reference_stage1 daemon forge_destructor; do
      if [ $c = reference_stage1 ]; then
        # An honest grading with the default limits, as a course runs it.
        rm -rf "$sub"; mkdir -p "$sub/$s1"; solution1; checks=(--full-marks); stages=1; limit=()
        grade_and_check || failed=1
      else
        bash "$(dirname "$0")/trust.sh" "$bin" "$src" $c || failed=1
      fi
      echo "--- $c with a grading beside it: $([ $failed = 0 ] && echo ok || echo FAILED)"
    done
    # Interrupted (as Ctrl-C does), not waited for: at that priority a grading can take minutes.
    touch "$work/stop"
    while kill -0 $background 2> /dev/null; do
      kill -INT "$(cat "$work/bomb.pid")" 2> /dev/null
      sleep 0.5
    done
    wait $background
    exit $failed ;;
  *) echo "unknown case $case"; exit 2 ;;
esac

grade_and_check
