// The GoogleTest main of the grading workspace (trusted; never part of a student tree's build).
// rt-grade links it into the stage test binaries of its workspace in place of gtest_main, and
// takes each unit test's verdict from the records this file writes, not from GoogleTest's
// output files, which student code in the same process could forge.
//
// The channel (docs/grading.md, "Unit-test verdicts"):
//   - rt-grade passes two descriptors, named by RT_GRADE_NONCE_FD and RT_GRADE_RESULT_FD: a pipe
//     holding a per-run random nonce, and one end of a socket pair for the records (a socket end
//     sends to its peer only: nothing in this process can read back or rewrite what was sent);
//   - a constructor of priority 101 reads the nonce and closes the pipe before any student
//     constructor can run (rt-grade refuses student objects with prioritized constructors,
//     .preinit_array or IFUNC resolvers, which would run earlier);
//   - a listener writes one record per finished test and one at the end, each carrying the
//     nonce, through raw system calls and functions of internal linkage (student objects have
//     every symbol but their API localized, so they cannot interpose write() either);
//   - rt-grade rejects any record without the nonce, and duplicates, so a forger that runs
//     after the listener (a destructor, an atexit handler) can only spoil its own grade.
// The residual risk, stated in docs/grading.md: code running in this process during the test
// can read this process's memory, so a forger that reconstructs the masked nonce and exits
// before the listener writes is not excluded by the channel; image tests (scored outside the
// process, on unseen views) are not exposed to it.
// Without those variables (a student building the workspace by hand) it is a plain gtest main.
#include <gtest/gtest.h>

#include <sys/syscall.h>
#include <unistd.h>

#include <cstdlib>

namespace {

constexpr int kNonceChars = 32;  // hex digits of 16 random bytes

// The nonce is kept XOR-ed with a mask, so it never sits in memory as a recognisable hex string.
unsigned char g_masked_nonce[kNonceChars];
unsigned char g_mask[kNonceChars];
int g_result_fd = -1;

// System calls without libc: a student definition of read/write/close cannot see the nonce.
long raw_syscall(long number, long a, long b, long c) {
#if defined(__x86_64__)
    long ret;
    asm volatile("syscall"
                 : "=a"(ret)
                 : "a"(number), "D"(a), "S"(b), "d"(c)
                 : "rcx", "r11", "memory");
    return ret;
#elif defined(__aarch64__)
    register long x8 asm("x8") = number;
    register long x0 asm("x0") = a;
    register long x1 asm("x1") = b;
    register long x2 asm("x2") = c;
    asm volatile("svc 0" : "+r"(x0) : "r"(x8), "r"(x1), "r"(x2) : "memory");
    return x0;
#else
    return ::syscall(number, a, b, c);
#endif
}

long raw_read(int fd, void* data, long size) {
    return raw_syscall(SYS_read, fd, long(data), size);
}
long raw_write(int fd, const void* data, long size) {
    return raw_syscall(SYS_write, fd, long(data), size);
}
void raw_close(int fd) {
    raw_syscall(SYS_close, fd, 0, 0);
}

int parse_fd(const char* text) {
    if (!text || !*text) return -1;
    int fd = 0;
    for (; *text; ++text) {
        if (*text < '0' || *text > '9' || fd > 100000) return -1;
        fd = fd * 10 + (*text - '0');
    }
    return fd;
}

bool is_hex(unsigned char c) {
    return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
}

// Runs before every constructor of default priority, the student's included.
__attribute__((constructor(101))) void take_channel() {
    const int nonce_fd = parse_fd(std::getenv("RT_GRADE_NONCE_FD"));
    const int result_fd = parse_fd(std::getenv("RT_GRADE_RESULT_FD"));
    if (nonce_fd < 3 || result_fd < 3) return;
    unsigned char nonce[kNonceChars];
    long got = 0;
    while (got < kNonceChars) {
        const long n = raw_read(nonce_fd, nonce + got, kNonceChars - got);
        if (n <= 0) break;
        got += n;
    }
    raw_close(nonce_fd);
    for (int i = 0; i < kNonceChars; ++i)
        if (got != kNonceChars || !is_hex(nonce[i])) return;  // no channel: nothing can pass
    // A mask from the kernel; the nonce itself is overwritten once masked.
    if (raw_syscall(SYS_getrandom, long(g_mask), kNonceChars, 0) != kNonceChars) return;
    for (int i = 0; i < kNonceChars; ++i) {
        g_masked_nonce[i] = nonce[i] ^ g_mask[i];
        static_cast<volatile unsigned char*>(nonce)[i] = 0;
    }
    g_result_fd = result_fd;
}

// A record: "RTG1 <nonce> <PASS|FAIL|END> <text>\n", built in a fixed buffer.
class Record {
  public:
    void add(const char* text) {
        while (*text && size_ < kCapacity - 1) data_[size_++] = *text++;
    }
    void add_nonce() {
        for (int i = 0; i < kNonceChars && size_ < kCapacity - 1; ++i)
            data_[size_++] = char(g_masked_nonce[i] ^ g_mask[i]);
    }
    void add_number(long n) {
        char digits[24];
        int k = 0;
        do {
            digits[k++] = char('0' + n % 10);
            n /= 10;
        } while (n > 0 && k < 23);
        while (k > 0 && size_ < kCapacity - 1) data_[size_++] = digits[--k];
    }
    void send() {
        data_[size_++] = '\n';
        long done = 0;
        while (done < size_) {
            const long n = raw_write(g_result_fd, data_ + done, size_ - done);
            if (n <= 0) break;
            done += n;
        }
        for (int i = 0; i < size_; ++i) static_cast<volatile char*>(data_)[i] = 0;
    }

  private:
    static constexpr int kCapacity = 1024;
    char data_[kCapacity];
    int size_ = 0;
};

class ChannelReporter : public ::testing::EmptyTestEventListener {
    void OnTestEnd(const ::testing::TestInfo& info) override {
        const bool passed = info.result()->Passed();
        passed_ += passed;
        failed_ += !passed;
        Record r;
        r.add("RTG1 ");
        r.add_nonce();
        r.add(passed ? " PASS " : " FAIL ");
        r.add(info.test_suite_name());
        r.add(".");
        r.add(info.name());
        r.send();
    }
    void OnTestProgramEnd(const ::testing::UnitTest&) override {
        Record r;
        r.add("RTG1 ");
        r.add_nonce();
        r.add(" END ");
        r.add_number(passed_);
        r.add(" ");
        r.add_number(failed_);
        r.send();
    }
    long passed_ = 0, failed_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    if (g_result_fd >= 0)
        ::testing::UnitTest::GetInstance()->listeners().Append(new ChannelReporter);
    return RUN_ALL_TESTS();
}
