// rt-worker: the grading worker (framework/remote/remote_call.h). Runs the student's code for a
// judge on the socket named by RT_REMOTE_FD; students never start it themselves.
#include <cstdio>
#include <cstdlib>

#include "remote/worker_serve.h"

int main() {
    const char* fd = std::getenv("RT_REMOTE_FD");
    if (!fd || std::atoi(fd) < 3) {
        std::fprintf(stderr,
                     "rt-worker: runs student code for a grading judge; it needs RT_REMOTE_FD\n");
        return 2;
    }
    return rt::remote::serve(std::atoi(fd));
}
