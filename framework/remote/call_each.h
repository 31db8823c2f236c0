// call_each: many calls of one student function at once, for tests that make thousands.
//
// In a student's own tree it is a plain loop. In a grading judge (remote_call.h) every call
// would otherwise cross to the worker and back alone (tens of microseconds each); call_each sends
// them in messages of kCallsPerMessage, and the worker answers each message with all its results.
#pragma once

#include <algorithm>
#include <tuple>
#include <type_traits>
#include <vector>

#include "remote/remote_call.h"

namespace rt::remote {

// True in a grading judge (judge_client.cpp); false everywhere else (the weak default in
// testing/stage_test.cpp).
bool judging();
// The call-list key of a judge's proxy (judge_proxies.cpp), or nullptr.
const char* proxy_key(const void* proxy);

inline constexpr std::size_t kCallsPerMessage = 4096;

template <class F>
struct Batch;
template <class R, class... P>
struct Batch<R(P...)> {
    template <class... A>
    static void run(const char* key, std::vector<std::tuple<A...>>& calls, std::vector<R>& out) {
        for (std::size_t begin = 0; begin < calls.size(); begin += kCallsPerMessage) {
            const std::size_t end = std::min(calls.size(), begin + kCallsPerMessage);
            Writer w;
            put(w, std::string("*") + key);
            put(w, std::uint64_t(end - begin));
            for (std::size_t i = begin; i < end; ++i)
                std::apply([&](auto&... a) { Remote<R(P...)>::send_args(w, a...); }, calls[i]);
            const std::string reply = call_worker(w.data(), key);
            Reader r(reply);
            for (std::size_t i = begin; i < end; ++i)
                out.push_back(std::apply(
                    [&](auto&... a) { return Remote<R(P...)>::receive_result(r, key, a...); },
                    calls[i]));
            Remote<R(P...)>::check(r, key);
        }
    }
};

}  // namespace rt::remote

namespace rt::testing {

// Calls `function` once per element of `calls` (a tuple of its arguments each), in order;
// returns what each call returned. Out-parameters (Hit&, ...) are written into the tuples.
template <auto function, class... A>
auto call_each(std::vector<std::tuple<A...>>& calls) {
    using Signature = std::remove_pointer_t<decltype(function)>;
    using Result = std::invoke_result_t<decltype(function), A&...>;
    std::vector<Result> results;
    results.reserve(calls.size());
    const char* key =
        remote::judging() ? remote::proxy_key(reinterpret_cast<const void*>(function)) : nullptr;
    if (!key) {
        for (auto& call : calls) results.push_back(std::apply(function, call));
        return results;
    }
    remote::Batch<Signature>::run(key, calls, results);
    return results;
}

// call_each of `count` calls, the i-th with the arguments `arguments(i)` returns (a tuple),
// made in order of i: a test's loop of calls with fresh random numbers, made at once.
template <auto function, class Arguments>
auto call_for(int count, Arguments arguments) {
    std::vector<decltype(arguments(0))> calls;
    calls.reserve(std::size_t(std::max(count, 0)));
    for (int i = 0; i < count; ++i) calls.push_back(arguments(i));
    return call_each<function>(calls);
}

}  // namespace rt::testing
