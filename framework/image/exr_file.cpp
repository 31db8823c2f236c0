#include "image/exr_file.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>

#include <exception>
#include <string>

#include "core/diagnostics.h"

namespace rt::image_files {
namespace {

// Where the channel of column 0, row 0 would be if the frame buffer started at the window's origin.
char* origin(float* base, const Imath::Box2i& window, int width, int stride_values, int channel) {
    const std::ptrdiff_t offset =
        -(std::ptrdiff_t(window.min.x) + std::ptrdiff_t(window.min.y) * width) * stride_values +
        channel;
    return reinterpret_cast<char*>(base + offset);
}

}  // namespace

void write_exr(const Image& image, const std::filesystem::path& file) {
    try {
        Imf::Header header(image.width, image.height);
        header.compression() = Imf::ZIP_COMPRESSION;
        for (const char* name : {"R", "G", "B"})
            header.channels().insert(name, Imf::Channel(Imf::FLOAT));
        // The image is rows of Color; in the double preset it is converted to float first.
        std::vector<float> values(image.pixels.size() * 3);
        for (std::size_t i = 0; i < image.pixels.size(); ++i)
            for (int c = 0; c < 3; ++c) values[i * 3 + std::size_t(c)] = float(image.pixels[i][c]);
        Imf::FrameBuffer frame;
        const char* names[3] = {"R", "G", "B"};
        for (int c = 0; c < 3; ++c)
            frame.insert(names[c],
                         Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(values.data() + c),
                                    sizeof(float) * 3, sizeof(float) * 3 * image.width));
        Imf::OutputFile out(file.c_str(), header);
        out.setFrameBuffer(frame);
        out.writePixels(image.height);
    } catch (const std::exception& e) {
        throw ImageError(file, std::string("writing failed (") + e.what() +
                                   "); check that the folder exists and is writable");
    }
}

DecodedImage read_exr(const std::filesystem::path& file) {
    DecodedImage out;
    // OpenEXR sizes its line-offset table from the header before we see it: a damaged header
    // claiming a huge image must be refused by OpenEXR's own check first.
    static const bool limited = [] {
        Imf::Header::setMaxImageSize(int(kMaxSide), int(kMaxSide));
        return true;
    }();
    (void)limited;
    try {
        Imf::InputFile in(file.c_str());
        const Imath::Box2i window = in.header().dataWindow();
        const std::int64_t width = std::int64_t(window.max.x) - window.min.x + 1;
        const std::int64_t height = std::int64_t(window.max.y) - window.min.y + 1;
        const Imf::ChannelList& channels = in.header().channels();
        const bool rgb =
            channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B");
        const bool grey = !rgb && channels.findChannel("Y");
        if (!rgb && !grey)
            throw ImageError(file,
                             "the EXR has neither R, G, B nor Y channels; re-export it "
                             "as RGB");
        out.channels = rgb ? 3 : 1;
        if (const std::string problem = size_problem(width, height, out.channels); !problem.empty())
            throw ImageError(file, problem);
        out.width = int(width);
        out.height = int(height);
        out.floating = true;
        out.bits = 32;
        out.values.resize(std::size_t(width) * std::size_t(height) * std::size_t(out.channels));
        Imf::FrameBuffer frame;
        const char* names[3] = {"R", "G", "B"};
        for (int c = 0; c < out.channels; ++c)
            frame.insert(
                rgb ? names[c] : "Y",
                Imf::Slice(Imf::FLOAT,
                           origin(out.values.data(), window, out.width, out.channels, c),
                           sizeof(float) * std::size_t(out.channels),
                           sizeof(float) * std::size_t(out.channels) * std::size_t(out.width)));
        in.setFrameBuffer(frame);
        in.readPixels(window.min.y, window.max.y);
    } catch (const ImageError&) {
        throw;
    } catch (const std::exception& e) {
        throw ImageError(file, std::string("cannot read the EXR (") + e.what() +
                                   "); the file is damaged or not an EXR: re-export it");
    }
    return out;
}

}  // namespace rt::image_files
