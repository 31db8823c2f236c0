#include "image/png_file.h"

#include <png.h>
#include <zlib.h>

#include <csetjmp>
#include <cstdio>
#include <memory>
#include <string>

#include "core/diagnostics.h"

namespace rt::image_files {
namespace {

// libpng reports errors by longjmp. Each sequence of libpng calls that can jump lives in a
// function of its own holding only plain data, so nothing with a destructor is jumped over.
struct PngErrors {
    char message[256] = "";
};

void on_error(png_structp png, png_const_charp text) {
    auto* errors = static_cast<PngErrors*>(png_get_error_ptr(png));
    std::snprintf(errors->message, sizeof errors->message, "%s", text);
    png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}  // e.g. unknown chunks: nothing to do

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& what,
                       const std::string& fix) {
    throw ImageError(file, what + "; " + fix);
}

struct Writer {
    PngErrors errors;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &errors, on_error, on_warning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    ~Writer() { png_destroy_write_struct(&png, &info); }
};

bool write_all(Writer& w, std::FILE* f, const Image8& image) {
    if (setjmp(png_jmpbuf(w.png))) return false;
    png_init_io(w.png, f);
    // OpenImageIO's settings (zlib level 6, default strategy; libpng alone would pick
    // Z_FILTERED), so the bytes of every reference image stay the same.
    png_set_compression_level(w.png, 6);
    png_set_compression_strategy(w.png, Z_DEFAULT_STRATEGY);
    png_set_IHDR(w.png, w.info, png_uint_32(image.width), png_uint_32(image.height), 8,
                 PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    // The chunks OpenImageIO 2.4 writes for an sRGB image: the reference images were made so.
    png_set_sRGB_gAMA_and_cHRM(w.png, w.info, PNG_sRGB_INTENT_ABSOLUTE);
    png_set_oFFs(w.png, w.info, 0, 0, PNG_OFFSET_PIXEL);
    png_text text{};
    text.compression = PNG_TEXT_COMPRESSION_NONE;
    text.key = const_cast<char*>("oiio:ColorSpace");
    text.text = const_cast<char*>("sRGB");
    png_set_text(w.png, w.info, &text, 1);
    png_write_info(w.png, w.info);
    for (int y = 0; y < image.height; ++y)
        png_write_row(w.png, image.data.data() + std::size_t(y) * std::size_t(image.width) * 3);
    png_write_end(w.png, nullptr);
    return true;
}

struct Reader {
    PngErrors errors;
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &errors, on_error, on_warning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    ~Reader() { png_destroy_read_struct(&png, &info, nullptr); }
};

struct Header {
    png_uint_32 width = 0, height = 0;
    int channels = 0, bits = 0;
    std::size_t row_bytes = 0;
};

// Reads the header and sets the transforms: palette to RGB, grey below 8 bits to 8,
// transparency to alpha, 16-bit samples in host order.
bool read_header(Reader& r, std::FILE* f, Header* h) {
    if (setjmp(png_jmpbuf(r.png))) return false;
    png_init_io(r.png, f);
    png_set_sig_bytes(r.png, 8);
    png_read_info(r.png, r.info);
    png_set_expand(r.png);
    if (png_get_bit_depth(r.png, r.info) == 16) png_set_swap(r.png);
    png_read_update_info(r.png, r.info);
    h->width = png_get_image_width(r.png, r.info);
    h->height = png_get_image_height(r.png, r.info);
    h->channels = png_get_channels(r.png, r.info);
    h->bits = png_get_bit_depth(r.png, r.info);
    h->row_bytes = png_get_rowbytes(r.png, r.info);
    return true;
}

bool read_rows(Reader& r, png_bytep* rows) {
    if (setjmp(png_jmpbuf(r.png))) return false;
    png_read_image(r.png, rows);
    png_read_end(r.png, nullptr);
    return true;
}

}  // namespace

void write_png(const Image8& image, const std::filesystem::path& file) {
    File f(std::fopen(file.c_str(), "wb"));
    if (!f) fail(file, "cannot create the file", "check that the folder exists and is writable");
    Writer w;
    if (!w.info) fail(file, "out of memory", "free some memory");
    if (!write_all(w, f.get(), image))
        fail(file, std::string("writing failed (") + w.errors.message + ")",
             "check that the disk is not full");
    if (std::fflush(f.get()) != 0 || std::ferror(f.get()))
        fail(file, "writing failed", "check that the disk is not full");
}

DecodedImage read_png(const std::filesystem::path& file) {
    File f(std::fopen(file.c_str(), "rb"));
    if (!f) fail(file, "cannot open the image", "check the path and its permissions");
    png_byte signature[8] = {};
    if (std::fread(signature, 1, 8, f.get()) != 8 || png_sig_cmp(signature, 0, 8) != 0)
        fail(file, "not a PNG file", "re-export it as PNG");
    Reader r;
    if (!r.info) fail(file, "out of memory", "free some memory");
    Header h;
    const auto damaged = [&] {
        fail(file, std::string("cannot decode the PNG (") + r.errors.message + ")",
             "the file is damaged or truncated: re-export it");
    };
    if (!read_header(r, f.get(), &h)) damaged();
    // Checked before anything is allocated for the pixels.
    if (const std::string problem = size_problem(h.width, h.height, h.channels); !problem.empty())
        throw ImageError(file, problem);
    std::vector<png_byte> raw(h.row_bytes * h.height);
    std::vector<png_bytep> rows(h.height);
    for (std::size_t y = 0; y < h.height; ++y) rows[y] = raw.data() + h.row_bytes * y;
    if (!read_rows(r, rows.data())) damaged();

    DecodedImage out;
    out.width = int(h.width);
    out.height = int(h.height);
    out.channels = h.channels;
    out.bits = h.bits;
    const std::size_t count = std::size_t(out.width) * out.height * std::size_t(out.channels);
    if (out.bits == 16) {
        out.values.resize(count);
        const auto* wide = reinterpret_cast<const std::uint16_t*>(raw.data());
        for (std::size_t i = 0; i < count; ++i) out.values[i] = float(wide[i]) / 65535.0f;
    } else {
        raw.resize(count);
        out.bytes = std::move(raw);
    }
    return out;
}

}  // namespace rt::image_files
