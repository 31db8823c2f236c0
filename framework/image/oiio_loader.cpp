#include "image/oiio_loader.h"

#include <dlfcn.h>

#include <mutex>
#include <string>

#include "core/diagnostics.h"
#include "image/image.h"
#include "image/oiio_plugin.h"

namespace rt::image_files {
namespace {

namespace fs = std::filesystem;

struct Plugin {
    decltype(&rt_oiio_read) read = nullptr;
    decltype(&rt_oiio_free) free = nullptr;
    std::string problem;  // why it could not be loaded
};

// RT_OIIO_PLUGIN names the module; otherwise it sits in ../lib beside the program (the build
// tree's and an install's layout), or where the build put it.
const Plugin& plugin() {
    static Plugin loaded;
    static std::once_flag once;
    std::call_once(once, [] {
        std::vector<fs::path> candidates;
        if (const char* env = std::getenv("RT_OIIO_PLUGIN")) candidates.emplace_back(env);
        std::error_code ec;
        const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
        if (!ec) candidates.push_back(exe.parent_path().parent_path() / "lib" / "librt_oiio.so");
#ifdef RT_OIIO_PLUGIN_PATH
        candidates.emplace_back(RT_OIIO_PLUGIN_PATH);
#endif
        std::string tried;
        for (const fs::path& path : candidates) {
            if (void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL)) {
                loaded.read =
                    reinterpret_cast<decltype(&rt_oiio_read)>(dlsym(module, "rt_oiio_read"));
                loaded.free =
                    reinterpret_cast<decltype(&rt_oiio_free)>(dlsym(module, "rt_oiio_free"));
                if (loaded.read && loaded.free) return;
                tried += (tried.empty() ? "" : ", ") + path.string() + " (not the plug-in)";
            } else {
                tried += (tried.empty() ? "" : ", ") + path.string();
            }
        }
        loaded.problem =
            "reading this format needs the OpenImageIO plug-in librt_oiio.so, which "
            "was not found (tried " +
            tried +
            "); build the target rt_oiio, set "
            "RT_OIIO_PLUGIN to its path, or convert the image to PNG or EXR";
    });
    return loaded;
}

}  // namespace

DecodedImage read_with_oiio(const fs::path& file) {
    const Plugin& p = plugin();
    if (!p.read) throw ImageError(one_line(file.string() + ": error: " + p.problem));
    RtOiioImage raw{};
    char error[512] = "";
    if (!p.read(file.c_str(), kMaxSide, kMaxPixels, &raw, error, sizeof error))
        throw ImageError(one_line(file.string() + ": error: cannot read the image (" + error +
                                  "); is it an image file? re-export it as PNG or EXR"));
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
