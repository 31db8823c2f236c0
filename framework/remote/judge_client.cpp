// The judge's end of the worker connection (remote_call.h): the socket the grader passed
// (RT_REMOTE_FD), or, outside grading, a worker this process starts itself (RT_REMOTE_WORKER,
// the path of rt-worker: how ctest checks the split without the grader).
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include "core/not_implemented.h"
#include "remote/call_each.h"
#include "remote/connection.h"
#include "remote/remote_call.h"

namespace rt::remote {
namespace {

std::vector<Callback>& pending_callbacks();

int parse_fd(const char* text) {
    if (!text || !*text) return -1;
    char* end = nullptr;
    const long fd = std::strtol(text, &end, 10);
    return *end == '\0' && fd >= 3 && fd < 65536 ? int(fd) : -1;
}

// Starts `worker` on one end of a new socket pair; returns the other end.
int start_worker(const char* worker) {
    int ends[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0) return -1;
    const pid_t pid = fork();
    if (pid == 0) {
        // The judge's test watchdog (testing/test_watch.h) limits the judge's CPU time for the
        // test under way; fork would hand that soft limit to the worker, which serves every test
        // and would be stopped once all of them together used it (a cold shader cache does).
        // The hard limit, a sandbox's, stays.
        rlimit cpu{};
        if (getrlimit(RLIMIT_CPU, &cpu) == 0 && cpu.rlim_cur != cpu.rlim_max) {
            cpu.rlim_cur = cpu.rlim_max;
            setrlimit(RLIMIT_CPU, &cpu);
        }
        dup2(ends[1], 3);
        fcntl(3, F_SETFD, 0);  // the worker's end survives exec even when it already was 3
        setenv("RT_REMOTE_FD", "3", 1);
        execl(worker, worker, "--serve", static_cast<char*>(nullptr));
        _exit(127);
    }
    close(ends[1]);
    return pid > 0 ? ends[0] : -1;
}

// The function a call-list key names: "intersect_sphere" of "intersect_sphere(const Ray& ...)".
std::string function_name(const char* key) {
    const std::string k(key);
    return k.substr(0, k.find('('));
}

class Client {
  public:
    Client() {
        fd_ = parse_fd(std::getenv("RT_REMOTE_FD"));
        if (fd_ < 0)
            if (const char* worker = std::getenv("RT_REMOTE_WORKER")) fd_ = start_worker(worker);
        signal(SIGPIPE, SIG_IGN);
        keep_freed_memory();
    }

    std::string call(const std::string& request, const char* what) {
        std::lock_guard lock(mutex_);
        if (fd_ < 0)
            throw RemoteError(
                "this test binary is a grading judge: it runs student code only in a worker "
                "(RT_REMOTE_FD or RT_REMOTE_WORKER), and has none");
        std::vector<Callback> callbacks;
        callbacks.swap(pending_callbacks());
        if (dead_ || !send_message(fd_, request)) lost(what);
        for (;;) {
            std::string reply;
            if (!receive_message(fd_, reply)) lost(what);
            Reader r(reply);
            std::uint8_t status = 0;
            std::uint64_t stubs = 0;
            get(r, status);
            get(r, stubs);
            if (!r.ok() || status > kCallback)
                throw RemoteError("malformed reply to " + function_name(what));
            if (stubs > stubs_seen_) count_stub_calls(stubs - stubs_seen_);
            stubs_seen_ = std::max(stubs_seen_, stubs);
            std::string rest = std::move(reply.erase(0, 1 + sizeof stubs));
            if (status == kDone) return rest;
            if (status == kThrew) throw std::runtime_error(rest);
            answer_callback(callbacks, rest, what);
        }
    }

    bool sent(std::uint64_t key) { return !sent_.insert(key).second; }

  private:
    [[noreturn]] void lost(const char* what) {
        dead_ = true;
        throw RemoteError("the process running your code ended during a call of " +
                          function_name(what) +
                          " (a crash, exit() or abort: see its output below)");
    }

    // The worker asks for a callback's value: the callback's number, then its arguments.
    void answer_callback(const std::vector<Callback>& callbacks, const std::string& message,
                         const char* what) {
        Reader r(message);
        std::uint32_t index = 0;
        get(r, index);
        if (!r.ok() || index >= callbacks.size())
            throw RemoteError("malformed callback during " + function_name(what));
        Writer out;
        callbacks[index](r, out);
        if (!r.ok() || !r.at_end())
            throw RemoteError("malformed callback during " + function_name(what));
        if (!send_message(fd_, out.data())) lost(what);
    }

    std::mutex mutex_;
    int fd_ = -1;
    bool dead_ = false;
    std::uint64_t stubs_seen_ = 0;
    std::set<std::uint64_t> sent_;
};

std::vector<Callback>& pending_callbacks() {
    thread_local std::vector<Callback> callbacks;
    return callbacks;
}

Client& client() {
    static Client c;
    return c;
}

}  // namespace

std::string call_worker(const std::string& request, const char* what) {
    return client().call(request, what);
}

bool judging() {
    return true;
}

bool already_sent(std::uint64_t key) {
    return client().sent(key);
}

std::uint32_t add_callback(Callback callback) {
    pending_callbacks().push_back(std::move(callback));
    return std::uint32_t(pending_callbacks().size() - 1);
}

}  // namespace rt::remote
