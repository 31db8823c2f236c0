// The judge's definitions of every function in the call lists (stage_api/calls.h), stage 09's
// GLSL-running ones included: each sends its call to the worker (remote_call.h). A judge links
// these instead of rt_stages, rt_render and rt_gpu_render, so no student code, and nothing that
// calls it, is in its process.
#include <map>

#include "remote/api_headers.h"
#include "remote/call_each.h"
#include "remote/remote_call.h"

namespace rt {

#define RT_DEFINE_PROXY(ret, name, params, args)                                  \
    ret name params {                                                             \
        return ::rt::remote::Remote<ret params>::call(RT_REMOTE_KEY(name, params) \
                                                          RT_REMOTE_ARGS args);   \
    }
RT_ALL_CALLS(RT_DEFINE_PROXY)
RT_GPU_CALLS(RT_DEFINE_PROXY)
#undef RT_DEFINE_PROXY

}  // namespace rt

namespace rt::remote {

const char* proxy_key(const void* proxy) {
    static const std::map<const void*, const char*> keys = {
#define RT_PROXY_KEY(ret, name, params, args)                                \
    {reinterpret_cast<const void*>(static_cast<ret(*) params>(&::rt::name)), \
     RT_REMOTE_KEY(name, params)},
        RT_ALL_CALLS(RT_PROXY_KEY)
#undef RT_PROXY_KEY
    };
    const auto it = keys.find(proxy);
    return it == keys.end() ? nullptr : it->second;
}

}  // namespace rt::remote
