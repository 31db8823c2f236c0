// The OpenImageIO plug-in's C interface. Formats other than PNG and EXR (JPEG, HDR, TIFF, ...)
// are read by OpenImageIO, which the framework loads with dlopen on first use: OpenImageIO's
// dependency tree costs about 0.3 s of start-up in every process that links it, and most
// processes (tests, grading children, `rt render`) only ever touch PNG and EXR files.
#pragma once

#include <cstddef>

extern "C" {

struct RtOiioImage {
    int width;
    int height;
    int channels;
    int floating;   // 1 for float formats (linear), 0 for integer formats scaled to [0, 1]
    int bits;       // bits per channel in the file
    float* values;  // width * height * channels, row 0 at the top; free with rt_oiio_free
};

// Reads `path`; on failure returns 0 and writes a one-line reason into `error`.
// Images with a side over `max_side` or more than `max_pixels` pixels are refused before their
// pixels are allocated.
int rt_oiio_read(const char* path, long long max_side, long long max_pixels, RtOiioImage* out,
                 char* error, std::size_t error_size);
void rt_oiio_free(RtOiioImage* image);

}  // extern "C"
