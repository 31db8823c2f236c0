#include "image/image.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>

#include "core/diagnostics.h"
#include "image/exr_file.h"
#include "image/oiio_loader.h"
#include "image/png_file.h"

namespace rt {

ImageError::ImageError(const std::filesystem::path& file, const std::string& problem)
    : std::runtime_error(one_line(file.string() + ": error: " + problem)),
      problem_(one_line(problem)) {}

float linear_to_srgb(float x) {
    if (!(x > 0)) return 0;  // also NaN
    if (x >= 1) return 1;
    return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1 / 2.4f) - 0.055f;
}

float srgb_to_linear(float x) {
    if (!(x > 0)) return 0;
    if (x >= 1) return 1;
    return x <= 0.04045f ? x / 12.92f : std::pow((x + 0.055f) / 1.055f, 2.4f);
}

namespace {

int srgb8_by_pow(float linear) {
    return int(std::lround(linear_to_srgb(linear) * 255));
}

std::uint32_t bits_of(float x) {
    return std::bit_cast<std::uint32_t>(x);
}

// srgb8_by_pow without pow, for the 2.4 million channels of a 1024x768 image (pow was a sixth of
// `rt render`'s time after the rendering, on one thread). The code steps up at 255 thresholds in
// (0, 1); each is found once, by bisection over the floats with srgb8_by_pow itself, so the codes
// are the same bit for bit (the codes rise with x: checked for every float in (0, 1), see
// Image.Srgb8TableIsThePowEncoding). A table from a float's top 16 bits gives the code at the
// start of its range; the thresholds then move it up by at most a step or two.
class Srgb8Table {
  public:
    Srgb8Table() {
        const std::uint32_t one = bits_of(1.0f);
        for (int k = 1; k <= 255; ++k) {
            std::uint32_t lo = 0, hi = one;  // code(lo) < k <= code(hi)
            while (hi - lo > 1) {
                const std::uint32_t mid = lo + (hi - lo) / 2;
                (srgb8_by_pow(std::bit_cast<float>(mid)) >= k ? hi : lo) = mid;
            }
            threshold_[k] = std::bit_cast<float>(hi);
        }
        threshold_[256] = std::numeric_limits<float>::infinity();
        start_.resize((one >> 16) + 1);
        for (std::uint32_t b = 0; b < start_.size(); ++b)
            start_[b] = std::uint8_t(srgb8_by_pow(std::bit_cast<float>(b << 16)));
    }
    std::uint8_t operator()(float x) const {
        if (!(x > 0)) return 0;  // also NaN
        if (x >= 1) return 255;
        int k = start_[bits_of(x) >> 16];
        while (x >= threshold_[k + 1]) ++k;
        return std::uint8_t(k);
    }

  private:
    std::array<float, 257> threshold_{};  // threshold_[k]: the least float of code k
    std::vector<std::uint8_t> start_;
};

const Srgb8Table& srgb8_table() {
    static const Srgb8Table table;
    return table;
}

}  // namespace

std::uint8_t encode_srgb8(float linear) {
    return srgb8_table()(linear);
}

Image8 to_image8(const Image& image) {
    Image8 out{image.width, image.height, std::vector<std::uint8_t>(image.pixels.size() * 3)};
    const Srgb8Table& encode = srgb8_table();
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) out.data[i * 3 + c] = encode(image.pixels[i][c]);
    return out;
}

namespace {

namespace files = image_files;

enum class Format { Png, Exr, Other };

// By content, not by name: a renamed file is still read; a PNG or EXR name on other content is
// reported as damaged rather than handed to OpenImageIO.
Format format_of(const std::filesystem::path& file) {
    if (!std::filesystem::is_regular_file(file))
        throw ImageError(file, "no such image file; check the path");
    std::error_code ec;
    if (std::filesystem::file_size(file, ec) == 0 && !ec)
        throw ImageError(file, "the image file is empty; re-export it");
    unsigned char magic[8] = {};
    std::ifstream(file, std::ios::binary).read(reinterpret_cast<char*>(magic), sizeof magic);
    static constexpr unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    static constexpr unsigned char kExr[4] = {0x76, 0x2f, 0x31, 0x01};
    if (std::memcmp(magic, kPng, 8) == 0) return Format::Png;
    if (std::memcmp(magic, kExr, 4) == 0) return Format::Exr;
    const std::string ext = file.extension().string();
    if (ext == ".png" || ext == ".exr")
        throw ImageError(file,
                         std::string(ext == ".png" ? "not a PNG" : "not an EXR") +
                             " file (its first bytes are wrong); the file is damaged or misnamed: "
                             "re-export it");
    return Format::Other;
}

files::DecodedImage decode(const std::filesystem::path& file) {
    switch (format_of(file)) {
        case Format::Png:
            return files::read_png(file);
        case Format::Exr:
            return files::read_exr(file);
        case Format::Other:
            break;
    }
    return files::read_with_oiio(file);
}

}  // namespace

namespace image_files {

std::string size_problem(std::int64_t width, std::int64_t height, int channels) {
    if (width <= 0 || height <= 0 || width > kMaxSide || height > kMaxSide ||
        width * height > kMaxPixels)
        return "the image is " + std::to_string(width) + " x " + std::to_string(height) +
               " pixels; images must be 1 to " + std::to_string(kMaxSide) +
               " pixels a side and at most " + std::to_string(kMaxPixels / 1'000'000) +
               " Mpixel: resize it";
    if (channels < 1 || channels > 4)
        return "the image has " + std::to_string(channels) +
               " channels; use grey, grey + alpha, RGB or RGBA";
    return "";
}

}  // namespace image_files

void check_image_output(const std::filesystem::path& file) {
    const std::string ext = file.extension().string();
    if (ext != ".exr" && ext != ".png")
        throw ImageError(file, "unknown image extension \"" + ext +
                                   "\"; use .png (sRGB, 8-bit) or .exr (linear float)");
    std::error_code ec;
    const auto folder = file.parent_path();
    if (!folder.empty() && !std::filesystem::is_directory(folder, ec))
        throw ImageError(file,
                         "the folder " + folder.string() + " does not exist; create it first");
}

void write_image(const Image& image, const std::filesystem::path& file) {
    check_image_output(file);
    if (file.extension() == ".exr")
        files::write_exr(image, file);
    else
        files::write_png(to_image8(image), file);
}

void write_image8(const Image8& image, const std::filesystem::path& file) {
    files::write_png(image, file);
}

Image8 read_image8(const std::filesystem::path& file) {
    const files::DecodedImage in = decode(file);
    const std::size_t count = std::size_t(in.width) * in.height;
    Image8 out{in.width, in.height, std::vector<std::uint8_t>(count * 3)};
    for (std::size_t i = 0; i < count; ++i)
        for (std::size_t c = 0; c < 3; ++c) {
            const std::size_t at = i * std::size_t(in.channels) + (in.channels >= 3 ? c : 0);
            // Exact for 8-bit files; other depths are rounded to the nearest 8-bit step.
            out.data[i * 3 + c] =
                !in.bytes.empty()
                    ? in.bytes[at]
                    : std::uint8_t(std::lround(std::clamp(in.values[at], 0.0f, 1.0f) * 255));
        }
    return out;
}

Image read_image(const std::filesystem::path& file, Encoding integer_encoding, ImageInfo* info) {
    const files::DecodedImage in = decode(file);
    if (info) *info = ImageInfo{in.channels, in.floating};
    const bool decode_srgb = !in.floating && integer_encoding == Encoding::Srgb;
    Image out(in.width, in.height);
    std::size_t bad = 0;
    for (std::size_t i = 0; i < out.pixels.size(); ++i) {
        float v[3];
        for (std::size_t c = 0; c < 3; ++c) {
            const float x = in.value(i * std::size_t(in.channels) + (in.channels >= 3 ? c : 0));
            v[c] = decode_srgb ? srgb_to_linear(x) : x;
        }
        if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2])) ++bad;
        out.pixels[i] = Color(v[0], v[1], v[2]);
    }
    if (bad > 0)
        throw ImageError(file,
                         std::to_string(bad) + " pixels are NaN or infinite; re-export the image");
    return out;
}

NonFinitePixels mark_non_finite_pixels(Image& image) {
    NonFinitePixels found;
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        const Color& c = image.pixels[i];
        if (std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b)) continue;
        if (found.count++ == 0) {
            found.first_x = int(i % std::size_t(image.width));
            found.first_y = int(i / std::size_t(image.width));
        }
        image.pixels[i] = Color(1, 0, 1);  // magenta, as a stub's pixel
    }
    return found;
}

std::string NonFinitePixels::describe(const std::string& scene) const {
    const std::string at = std::to_string(first_x) + "," + std::to_string(first_y);
    return scene + ": " + std::to_string(count) +
           " pixels are not a number or infinite, shown magenta (the first at " + at +
           "): look for a 0/0, 0 * inf or inf - inf in their shading; rt render " + scene +
           " --debug-pixel " + at + " prints that pixel's rays (docs/conventions.md#colour)";
}

}  // namespace rt
