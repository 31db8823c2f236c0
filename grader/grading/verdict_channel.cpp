#include "grading/verdict_channel.h"

#include <fcntl.h>
#include <sys/random.h>
#include <sys/socket.h>
#include <unistd.h>

#include <sstream>

namespace rt::grader {

VerdictChannel::VerdictChannel() {
    unsigned char bytes[16];
    if (getrandom(bytes, sizeof bytes, 0) != ssize_t(sizeof bytes)) return;
    static const char digits[] = "0123456789abcdef";
    for (unsigned char b : bytes) {
        nonce.push_back(digits[b >> 4]);
        nonce.push_back(digits[b & 15]);
    }
    int p[2];
    if (pipe2(p, O_CLOEXEC) != 0) return;
    const bool written = write(p[1], nonce.data(), nonce.size()) == ssize_t(nonce.size());
    close(p[1]);
    nonce_read = p[0];
    int s[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, s) != 0) return;
    our_end = s[0];
    child_end = s[1];
    // Our end never sends: the child's end has nothing to read, ever.
    shutdown(our_end, SHUT_WR);
    ok = written;
}

VerdictChannel::~VerdictChannel() {
    for (int fd : {nonce_read, child_end, our_end})
        if (fd >= 0) close(fd);
}

std::string VerdictChannel::records() {
    if (child_end >= 0) {
        close(child_end);  // our copy: the read below ends when the child's copies are gone
        child_end = -1;
    }
    std::string text;
    char buffer[4096];
    fcntl(our_end, F_SETFL, O_NONBLOCK);  // the child has exited; a grandchild must not block us
    while (text.size() < (64u << 10)) {
        const ssize_t n = read(our_end, buffer, sizeof buffer);
        if (n <= 0) break;
        text.append(buffer, std::size_t(n));
    }
    return text;
}

bool channel_passed(const std::string& records, const std::string& nonce, const std::string& test,
                    std::string& why) {
    const std::string prefix = "RTG1 " + nonce + " ";
    std::istringstream lines(records);
    std::string line;
    int mine = 0, passes = 0, ends = 0;
    bool end_ok = false;
    while (std::getline(lines, line)) {
        if (!line.starts_with(prefix)) {
            why =
                "the test's result channel holds a record that did not come from the test "
                "runner (tampering?)";
            return false;
        }
        const std::string rest = line.substr(prefix.size());
        if (rest.starts_with("END ")) {
            ++ends;
            end_ok = rest == "END 1 0";
        } else if (rest.starts_with("PASS ") || rest.starts_with("FAIL ")) {
            if (rest.substr(5) != test) {
                why = "the result channel names a test that was not run (tampering?)";
                return false;
            }
            ++mine;
            passes += rest.starts_with("PASS ");
        } else {
            why = "the test's result channel holds a malformed record (tampering?)";
            return false;
        }
    }
    if (mine == 0) {
        why = "the test produced no result (it exited early?)";
        return false;
    }
    if (mine != 1 || ends != 1) {
        why = "the result channel holds duplicate records (tampering?)";
        return false;
    }
    return passes == 1 && end_ok;
}

}  // namespace rt::grader
