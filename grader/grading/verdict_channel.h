// The unit-test verdict channel between rt-grade and the trusted test main (test_main.cpp).
//
// The child gets two descriptors: a pipe holding a per-run random nonce (read once by the
// trusted main before any student constructor runs), and one end of a socket pair for its
// records. A socket end can only send to its peer: the child can never read back what it (or
// the trusted listener) sent, cannot reopen it through /proc/self/fd (sockets cannot be
// opened), and anything it adds besides the listener's records shows up as a duplicate or a
// record without the nonce. The trusted side reads its own end after the child has exited.
#pragma once

#include <string>

namespace rt::grader {

struct VerdictChannel {
    std::string nonce;    // 32 hex digits
    int nonce_read = -1;  // the child's RT_GRADE_NONCE_FD
    int child_end = -1;   // the child's RT_GRADE_RESULT_FD (send only, in effect)
    int our_end = -1;     // read by the grader
    bool ok = false;
    VerdictChannel();
    ~VerdictChannel();
    VerdictChannel(const VerdictChannel&) = delete;
    VerdictChannel& operator=(const VerdictChannel&) = delete;
    // After the child has exited: every byte it sent (at most 64 KiB).
    std::string records();
};

constexpr int kNonceFd = 3, kResultFd = 4;
// The judge's and the worker's end of their socket (framework/remote/, RT_REMOTE_FD).
constexpr int kRemoteFd = 5;

// The verdict: every record carries the nonce (else the channel was tampered with), exactly one
// record names this test and says PASS, the program's end record counts 1 passed and 0 failed.
// The caller also requires exit code 0.
bool channel_passed(const std::string& records, const std::string& nonce, const std::string& test,
                    std::string& why);

}  // namespace rt::grader
