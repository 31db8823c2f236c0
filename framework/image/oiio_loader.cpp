#include "image/oiio_loader.h"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "core/diagnostics.h"
#include "image/image.h"

namespace rt::image_files {
namespace {

namespace fs = std::filesystem;

template <typename F>
bool find(void* module, const char* name, F& out) {
    out = reinterpret_cast<F>(dlsym(module, name));
    return out != nullptr;
}

}  // namespace

OiioPlugin open_oiio_plugin(const std::vector<fs::path>& candidates) {
    OiioPlugin loaded;
    std::string tried;
    for (std::size_t k = 0; k < candidates.size(); ++k) {
        const fs::path& path = candidates[k];
        // The program's ../lib is usually where the build put it: try (and name) it once.
        if (std::find(candidates.begin(), candidates.begin() + long(k), path) !=
            candidates.begin() + long(k))
            continue;
        if (void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL)) {
            if (find(module, "rt_oiio_read", loaded.read) &&
                find(module, "rt_oiio_free", loaded.free) &&
                find(module, "rt_oiio_textures_create", loaded.textures_create) &&
                find(module, "rt_oiio_textures_add", loaded.textures_add) &&
                find(module, "rt_oiio_textures_lookup", loaded.textures_lookup) &&
                find(module, "rt_oiio_textures_destroy", loaded.textures_destroy) &&
                find(module, "rt_oiio_environment_add", loaded.environment_add) &&
                find(module, "rt_oiio_environment_lookup", loaded.environment_lookup))
                return loaded;
            loaded = OiioPlugin{};
            tried += (tried.empty() ? "" : ", ") + path.string() + " (not the plug-in)";
        } else {
            tried += (tried.empty() ? "" : ", ") + path.string();
        }
    }
    loaded.problem = "the OpenImageIO plug-in librt_oiio.so, which was not found (tried " + tried +
                     "); build the target rt_oiio or set RT_OIIO_PLUGIN to its path";
    return loaded;
}

const OiioPlugin& oiio_plugin() {
    static const OiioPlugin loaded = [] {
        std::vector<fs::path> candidates;
        if (const char* env = std::getenv("RT_OIIO_PLUGIN")) candidates.emplace_back(env);
        std::error_code ec;
        const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
        if (!ec) candidates.push_back(exe.parent_path().parent_path() / "lib" / "librt_oiio.so");
#ifdef RT_OIIO_PLUGIN_PATH
        candidates.emplace_back(RT_OIIO_PLUGIN_PATH);
#endif
        return open_oiio_plugin(candidates);
    }();
    return loaded;
}

DecodedImage read_with_oiio(const fs::path& file) {
    const OiioPlugin& p = oiio_plugin();
    if (!p.read)
        throw ImageError(file, "reading this format needs " + p.problem +
                                   ", or convert the image to PNG or EXR");
    RtOiioImage raw{};
    char error[512] = "";
    if (!p.read(file.c_str(), kMaxSide, kMaxPixels, &raw, error, sizeof error))
        throw ImageError(file, std::string("cannot read the image (") + error +
                                   "); is it an image file? re-export it as PNG or EXR");
    DecodedImage out;
    out.width = raw.width;
    out.height = raw.height;
    out.channels = raw.channels;
    out.floating = raw.floating != 0;
    out.bits = raw.bits;
    out.values.assign(raw.values, raw.values + std::size_t(raw.width) * raw.height * raw.channels);
    p.free(&raw);
    return out;
}

}  // namespace rt::image_files
