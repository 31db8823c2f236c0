#include "image/image.h"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <memory>

namespace rt {

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

Image8 to_image8(const Image& image) {
    Image8 out{image.width, image.height, std::vector<std::uint8_t>(image.pixels.size() * 3)};
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            out.data[i * 3 + c] = std::uint8_t(std::lround(linear_to_srgb(image.pixels[i][c]) * 255));
    return out;
}

namespace {

// OpenImageIO's messages may span lines; errors here are one line.
std::string one_line(std::string text) {
    for (char& c : text)
        if (c == '\n' || c == '\r') c = ' ';
    while (!text.empty() && text.back() == ' ') text.pop_back();
    return text;
}

void write_pixels(const std::filesystem::path& file, int width, int height, OIIO::TypeDesc type,
                  const void* data, bool linear) {
    auto out = OIIO::ImageOutput::create(file.string());
    if (!out)
        throw ImageError(file.string() + ": error: cannot write this image type (" +
                         one_line(OIIO::geterror()) + "); use a .png or .exr file name");
    OIIO::ImageSpec spec(width, height, 3, type);
    spec.attribute("oiio:ColorSpace", linear ? "Linear" : "sRGB");
    if (!out->open(file.string(), spec) || !out->write_image(type, data) || !out->close())
        throw ImageError(file.string() + ": error: writing failed (" + one_line(out->geterror()) +
                         "); check that the folder exists and is writable");
}

}  // namespace

void check_image_output(const std::filesystem::path& file) {
    const std::string ext = file.extension().string();
    if (ext != ".exr" && ext != ".png")
        throw ImageError(file.string() + ": error: unknown image extension \"" + ext +
                         "\"; use .png (sRGB, 8-bit) or .exr (linear float)");
    std::error_code ec;
    const auto folder = file.parent_path();
    if (!folder.empty() && !std::filesystem::is_directory(folder, ec))
        throw ImageError(file.string() + ": error: the folder " + folder.string() +
                         " does not exist; create it first");
}

void write_image(const Image& image, const std::filesystem::path& file) {
    const std::string ext = file.extension().string();
    if (ext == ".exr") {
        write_pixels(file, image.width, image.height, OIIO::TypeDesc::FLOAT, image.pixels.data(),
                     true);
    } else if (ext == ".png") {
        write_image8(to_image8(image), file);
    } else {
        throw ImageError(file.string() + ": error: unknown image extension \"" + ext +
                         "\"; use .png (sRGB, 8-bit) or .exr (linear float)");
    }
}

void write_image8(const Image8& image, const std::filesystem::path& file) {
    write_pixels(file, image.width, image.height, OIIO::TypeDesc::UINT8, image.data.data(), false);
}

namespace {

// Opens an image for reading, or throws the ImageError naming the file and what to check.
std::unique_ptr<OIIO::ImageInput> open_image(const std::filesystem::path& file, const char* hint) {
    if (!std::filesystem::is_regular_file(file))
        throw ImageError(file.string() + ": error: no such image file; check the path");
    auto in = OIIO::ImageInput::open(file.string());
    if (!in)
        throw ImageError(file.string() + ": error: cannot read image (" + one_line(OIIO::geterror()) +
                         "); " + hint);
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.width > 16384 || spec.height > 16384 ||
        spec.nchannels < 1 || spec.nchannels > 4)
        throw ImageError(file.string() + ": error: unsupported size or channel count");
    return in;
}

}  // namespace

Image8 read_image8(const std::filesystem::path& file) {
    auto in = open_image(file, "is it a PNG?");
    const OIIO::ImageSpec& spec = in->spec();
    const int channels = spec.nchannels;
    std::vector<std::uint8_t> raw(std::size_t(spec.width) * spec.height * channels);
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, raw.data()))
        throw ImageError(file.string() + ": error: cannot decode image (" + one_line(in->geterror()) + ")");
    Image8 out{spec.width, spec.height, std::vector<std::uint8_t>(std::size_t(spec.width) * spec.height * 3)};
    for (std::size_t i = 0; i < std::size_t(spec.width) * spec.height; ++i)
        for (int c = 0; c < 3; ++c)
            out.data[i * 3 + c] = raw[i * channels + (channels >= 3 ? c : 0)];
    return out;
}

Image read_image(const std::filesystem::path& file, Encoding integer_encoding) {
    auto in = open_image(file, "is it an EXR, HDR, PNG or JPEG?");
    const OIIO::ImageSpec& spec = in->spec();
    const int channels = spec.nchannels;
    std::vector<float> raw(std::size_t(spec.width) * spec.height * channels);
    // OpenImageIO scales integer formats to [0, 1] when reading them as float.
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, raw.data()))
        throw ImageError(file.string() + ": error: cannot decode image (" + one_line(in->geterror()) + ")");
    const bool floating = spec.format.is_floating_point();
    const bool decode = !floating && integer_encoding == Encoding::Srgb;
    Image out(spec.width, spec.height);
    std::size_t bad = 0;
    for (std::size_t i = 0; i < out.pixels.size(); ++i) {
        float v[3];
        for (int c = 0; c < 3; ++c) {
            const float x = raw[i * channels + (channels >= 3 ? c : 0)];
            v[c] = decode ? srgb_to_linear(x) : x;
        }
        if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2])) ++bad;
        out.pixels[i] = Color(v[0], v[1], v[2]);
    }
    if (bad > 0)
        throw ImageError(file.string() + ": error: " + std::to_string(bad) +
                         " pixels are NaN or infinite; re-export the image");
    return out;
}

}  // namespace rt
