// Calls of student code across the judge-worker boundary (docs/grading.md, "Unit-test verdicts").
//
// In grading, a stage's test binary is a *judge*: the tests, their assertions and GoogleTest, but
// no student code and nothing that calls it. Every such function is a proxy instead
// (judge_proxies.cpp), generated from the call lists in stage_api/calls.h: it sends its
// arguments to the *worker* (the framework with the student's objects, in a jail of its own),
// which makes the real call and sends back the return value and whatever the function may
// write through its parameters. So a test's verdict is what the judge's assertions say about the
// values the worker returned, and nothing the worker does can reach the judge's memory.
//
// A parameter's role follows from its declared type: a value or const reference is sent, a
// non-const reference is sent and read back, a non-const pointer likewise when not null.
#pragma once

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "remote/wire_types.h"
#include "render/prepare.h"

namespace rt::remote {

// The worker died, answered malformed bytes or threw: the judge's test fails with this message.
struct RemoteError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Sends a request, returns the reply's values (judge side, judge_client.cpp). Throws RemoteError.
// While it waits, the worker may call back into the judge (callbacks below).
std::string call_worker(const std::string& request, const char* what);

// Judge side: true when this connection already sent the scene of hash `key` (and marks it
// sent), so a call passes its handle only.
bool already_sent(std::uint64_t key);
// Judge side: a callback the worker may invoke during the next call (a test's IncomingRadiance):
// reads its arguments, writes its result. Returns its number in that call.
using Callback = std::function<void(Reader&, Writer&)>;
std::uint32_t add_callback(Callback callback);

// Worker side (worker_serve.cpp): the scene of handle `key`, decoded from `r` when `r` holds it;
// a description (Scene) or a prepared scene, each kept apart.
template <class S>
const S& held_scene(std::uint64_t key, bool in_request, Reader& r);
// Worker side: calls back the judge's callback `index` with `arguments`; returns its result.
std::string call_judge(std::uint32_t index, const std::string& arguments);

// A parameter of declared type P: how the judge sends it and reads it back, and how the worker
// holds it for the call.
template <class T>
struct Input {
    static void send(Writer& w, const T& v) { put(w, v); }
    static void receive(Reader&, const T&) {}
    struct Holder {
        Storage<T> value;
        void read(Reader& r) { get(r, value); }
        const T& arg() { return view(value); }
        void write(Writer&) {}
    };
};
template <class T>
struct InOut {
    static void send(Writer& w, const T& v) { put(w, v); }
    static void receive(Reader& r, T& v) { get(r, v); }
    struct Holder {
        T value{};
        void read(Reader& r) { get(r, value); }
        T& arg() { return value; }
        void write(Writer& w) { put(w, value); }
    };
};
template <class T>
struct InOutPointer {
    static void send(Writer& w, T* p) {
        put(w, p != nullptr);
        if (p) put(w, *p);
    }
    static void receive(Reader& r, T* p) {
        if (p) get(r, *p);
    }
    struct Holder {
        bool present = false;
        T value{};
        void read(Reader& r) {
            get(r, present);
            if (present) get(r, value);
        }
        T* arg() { return present ? &value : nullptr; }
        void write(Writer& w) {
            if (present) put(w, value);
        }
    };
};

template <class P>
struct Param : Input<std::remove_cvref_t<P>> {};
template <class T>
struct Param<T&> : InOut<T> {};
template <class T>
struct Param<const T&> : Input<T> {};
template <class T>
struct Param<T*> : InOutPointer<T> {};

// A scene crosses once per connection: afterwards by its hash (a test calls with one scene
// thousands of times). The worker keeps what it was sent; it cannot change the judge's copy.
template <class S>  // Scene or PreparedScene
struct SceneInput {
    static void send(Writer& w, const S& scene) {
        Writer hash{Writer::HashOnly{}};
        put(hash, scene);
        const std::uint64_t key = hash.digest();
        const bool held = already_sent(key);
        put(w, key);
        put(w, !held);
        if (!held) put(w, scene);
    }
    static void receive(Reader&, const S&) {}
    struct Holder {
        const S* scene = nullptr;
        void read(Reader& r) {
            std::uint64_t key = 0;
            bool in_request = false;
            get(r, key);
            get(r, in_request);
            scene = &held_scene<S>(key, in_request, r);
        }
        const S& arg() { return *scene; }
        void write(Writer&) {}
    };
};
template <>
struct Input<Scene> : SceneInput<Scene> {};
template <>
struct Input<PreparedScene> : SceneInput<PreparedScene> {};

// A scene the function may change (build_acceleration) crosses in full, both ways.
template <>
struct InOut<PreparedScene> {
    static void send(Writer& w, const PreparedScene& v) { put(w, v); }
    static void receive(Reader& r, PreparedScene& v) { get(r, v); }
    struct Holder {
        PreparedScene value;
        void read(Reader& r) {
            get(r, value);
            load_texture_system(value);  // OpenImageIO's cannot cross (wire_types.cpp)
        }
        PreparedScene& arg() { return value; }
        void write(Writer& w) { put(w, value); }
    };
};

// A test's incoming radiance (stage 10's indirect_diffuse) stays in the judge: the worker's
// stand-in calls back for each ray.
template <>
struct Input<IncomingRadiance> {
    static void send(Writer& w, const IncomingRadiance& incoming) {
        put(w, add_callback([&incoming](Reader& r, Writer& out) {
                Ray ray;
                get(r, ray);
                put(out, incoming(ray));
            }));
    }
    static void receive(Reader&, const IncomingRadiance&) {}
    struct Holder : IncomingRadiance {
        std::uint32_t index = 0;
        void read(Reader& r) { get(r, index); }
        const IncomingRadiance& arg() { return *this; }
        void write(Writer&) {}
        Color operator()(const Ray& ray) const override {
            Writer w;
            put(w, ray);
            const std::string reply = call_judge(index, w.data());
            Reader r(reply);
            Color c{0};
            get(r, c);
            return c;
        }
    };
};

// An observer of a trace (the ray-tree debugger's) cannot cross: the judge passes none.
template <>
struct InOutPointer<TraceObserver> {
    static void send(Writer&, TraceObserver* p) {
        if (p) throw RemoteError("a TraceObserver cannot be passed to the grading worker");
    }
    static void receive(Reader&, TraceObserver*) {}
    struct Holder {
        void read(Reader&) {}
        TraceObserver* arg() { return nullptr; }
        void write(Writer&) {}
    };
};

template <class F>
struct Remote;

template <class R, class... P>
struct Remote<R(P...)> {
    // The judge's side: the body of a proxy.
    static R call(const char* key, P... args) {
        Writer w;
        put(w, std::string(key));
        send_args(w, args...);
        const std::string reply = call_worker(w.data(), key);
        Reader r(reply);
        if constexpr (std::is_void_v<R>) {
            receive_result(r, key, args...);
            check(r, key);
        } else {
            R result = receive_result(r, key, args...);
            check(r, key);
            return result;
        }
    }

    static void send_args(Writer& w, P... args) { (Param<P>::send(w, args), ...); }

    // The return value, then what the call wrote through its parameters.
    static R receive_result(Reader& r, const char*, P... args) {
        if constexpr (std::is_void_v<R>) {
            (Param<P>::receive(r, args), ...);
        } else {
            R result{};
            get(r, result);
            (Param<P>::receive(r, args), ...);
            return result;
        }
    }

    static void check(const Reader& r, const char* key) {
        if (!r.ok() || !r.at_end())
            throw RemoteError(std::string("the worker's reply to ") + key + " is malformed");
    }

    // The worker's side: reads the arguments, makes the call, writes the results.
    template <auto function>
    static void serve(Reader& r, Writer& w) {
        serve_with<function>(r, w, std::index_sequence_for<P...>{});
    }

  private:
    template <auto function, std::size_t... I>
    static void serve_with(Reader& r, Writer& w, std::index_sequence<I...>) {
        std::tuple<typename Param<P>::Holder...> held;
        (std::get<I>(held).read(r), ...);
        if (!r.ok()) throw RemoteError("malformed request");
        if constexpr (std::is_void_v<R>) {
            function(std::get<I>(held).arg()...);
        } else {
            const R result = function(std::get<I>(held).arg()...);
            put(w, result);
        }
        (std::get<I>(held).write(w), ...);
    }
};

}  // namespace rt::remote

// The call lists' entries, X(return type, name, (parameters), (arguments)).
#define RT_REMOTE_ARGS(...) __VA_OPT__(, ) __VA_ARGS__
#define RT_REMOTE_KEY(name, params) #name #params
