// Not a grading judge: the program calls student code itself (rt, a stage's tests in a student's
// tree), so call_each loops and nothing crosses to a worker. Part of rt_render, which a judge
// never links; a judge links judge_client.cpp and judge_proxies.cpp instead.
#include "remote/call_each.h"

namespace rt::remote {

bool judging() {
    return false;
}
const char* proxy_key(const void*) {
    return nullptr;
}
std::string call_worker(const std::string&, const char* what) {
    throw RemoteError(std::string("no grading worker for ") + what);
}
bool already_sent(std::uint64_t) {
    return false;
}
std::uint32_t add_callback(Callback) {
    return 0;
}

}  // namespace rt::remote
