// The OpenImageIO plug-in (a shared module loaded by oiio_loader.cpp; see oiio_plugin.h).
#include "image/oiio_plugin.h"

#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {

int failed(char* error, std::size_t size, const std::string& why) {
    std::snprintf(error, size, "%s", why.c_str());
    return 0;
}

}  // namespace

extern "C" int rt_oiio_read(const char* path, long long max_side, long long max_pixels,
                            RtOiioImage* out, char* error, std::size_t error_size) {
    std::memset(out, 0, sizeof *out);
    auto in = OIIO::ImageInput::open(path);
    if (!in) return failed(error, error_size, OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.width > max_side || spec.height > max_side ||
        (long long)spec.width * spec.height > max_pixels || spec.nchannels < 1)
        return failed(error, error_size,
                      "the image is " + std::to_string(spec.width) + " x " +
                          std::to_string(spec.height) + " pixels, outside the supported sizes");
    const int channels = spec.nchannels < 4 ? spec.nchannels : 4;
    const std::size_t count = std::size_t(spec.width) * spec.height * channels;
    auto* values = static_cast<float*>(std::malloc(count * sizeof(float)));
    if (!values) return failed(error, error_size, "out of memory");
    // OpenImageIO scales integer formats to [0, 1] when reading them as float.
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, values)) {
        std::free(values);
        return failed(error, error_size, in->geterror());
    }
    out->width = spec.width;
    out->height = spec.height;
    out->channels = channels;
    out->floating = spec.format.is_floating_point() ? 1 : 0;
    out->bits = int(spec.format.size() * 8);
    out->values = values;
    return 1;
}

extern "C" void rt_oiio_free(RtOiioImage* image) {
    std::free(image->values);
    image->values = nullptr;
}
