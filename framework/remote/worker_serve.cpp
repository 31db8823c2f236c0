// The worker: serves a judge's calls with the real functions (the framework and the student's
// objects), one request at a time, until the judge closes the connection.
#include "remote/worker_serve.h"

#include <map>
#include <memory>
#include <string_view>
#include <unordered_map>

#include "core/not_implemented.h"
#include "remote/api_headers.h"
#include "remote/connection.h"
#include "remote/remote_call.h"
#include "render/prepare.h"

namespace rt::remote {
namespace {

int g_fd = -1;

using Handler = void (*)(Reader&, Writer&);

const std::unordered_map<std::string_view, Handler>& handlers() {
    static const std::unordered_map<std::string_view, Handler> table = {
#define RT_HANDLER(ret, name, params, args) \
    {RT_REMOTE_KEY(name, params),           \
     &Remote<ret params>::serve<static_cast<ret(*) params>(&::rt::name)>},
        RT_ALL_CALLS(RT_HANDLER) RT_GPU_CALLS(RT_HANDLER)
#undef RT_HANDLER
    };
    return table;
}

std::string reply(Status status, const std::string& body) {
    Writer w;
    put(w, std::uint8_t(status));
    put(w, std::uint64_t(stub_calls_total()));
    w.bytes(body.data(), body.size());
    return std::move(w.data());
}

// A request: the call's key and its arguments, or "*" + the key, a count and that many calls'
// arguments (rt::testing::call_each).
std::string serve_one(const std::string& request) {
    Reader r(request);
    std::string key;
    get(r, key);
    const bool batch = key.starts_with("*");
    std::uint64_t count = 1;
    if (batch) {
        key.erase(0, 1);
        get(r, count);
    }
    const auto it = handlers().find(key);
    if (!r.ok() || it == handlers().end())
        return reply(kThrew, "the worker has no function " + key.substr(0, 200));
    Writer out;
    try {
        for (std::uint64_t i = 0; i < count && r.ok(); ++i) it->second(r, out);
    } catch (const std::exception& e) {
        return reply(kThrew, e.what());
    }
    if (!r.ok() || !r.at_end()) return reply(kThrew, "malformed request for " + key);
    return reply(kDone, out.data());
}

}  // namespace

template <class S>
const S& held_scene(std::uint64_t key, bool in_request, Reader& r) {
    static std::map<std::uint64_t, std::unique_ptr<S>> scenes;
    auto& held = scenes[key];
    if (in_request) {
        held = std::make_unique<S>();
        get(r, *held);
        if constexpr (std::is_same_v<S, PreparedScene>) load_texture_system(*held);
    }
    if (!held) throw RemoteError("the judge named a scene the worker does not hold");
    return *held;
}
template const Scene& held_scene<Scene>(std::uint64_t, bool, Reader&);
template const PreparedScene& held_scene<PreparedScene>(std::uint64_t, bool, Reader&);

std::string call_judge(std::uint32_t index, const std::string& arguments) {
    Writer w;
    put(w, index);
    w.bytes(arguments.data(), arguments.size());
    std::string answer;
    if (!send_message(g_fd, reply(kCallback, w.data())) || !receive_message(g_fd, answer))
        throw RemoteError("the judge went away during a callback");
    return answer;
}

int serve(int fd) {
    g_fd = fd;
    keep_freed_memory();
    for (std::string request; receive_message(fd, request);)
        if (!send_message(fd, serve_one(request))) break;
    return 0;
}

}  // namespace rt::remote
