// Images: sRGB encoding, PNG/EXR round trips, and the comparison the image tests and the grader use.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>

#include "core/source_dir.h"
#include "core/split_mix64.h"
#include "image/compare.h"
#include "image/image.h"

#include <png.h>
#include <zlib.h>

namespace rt {
namespace {

std::filesystem::path temp_file(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / "rt-framework-tests";
    std::filesystem::create_directories(dir);
    return dir / name;
}

Image8 gradient(int w, int h) {
    Image8 img{w, h, std::vector<std::uint8_t>(std::size_t(w) * h * 3)};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            img.at(x, y)[0] = std::uint8_t(x * 7);
            img.at(x, y)[1] = std::uint8_t(y * 5);
            img.at(x, y)[2] = 128;
        }
    return img;
}

// Fixed points of IEC 61966-2-1: 0, 1, the linear segment, and mid grey 0.5 -> 0.7354.
TEST(Srgb, KnownValues) {
    EXPECT_EQ(linear_to_srgb(0), 0);
    EXPECT_EQ(linear_to_srgb(1), 1);
    EXPECT_NEAR(linear_to_srgb(0.002f), 0.002f * 12.92f, 1e-7);
    EXPECT_NEAR(linear_to_srgb(0.5f), 0.735357f, 1e-5);
    EXPECT_NEAR(srgb_to_linear(linear_to_srgb(0.3f)), 0.3f, 1e-6);
}

// Out-of-range and NaN values clamp rather than wrap around in 8 bits.
TEST(Srgb, ClampsAndNaN) {
    Image img(3, 1);
    img.pixels = {Color(-1, 2, 0.5f), Color(std::nanf(""), 1e30f, 0), Color(0)};
    const Image8 out = to_image8(img);
    EXPECT_EQ(out.at(0, 0)[0], 0);
    EXPECT_EQ(out.at(0, 0)[1], 255);
    EXPECT_EQ(out.at(0, 0)[2], 188);  // round(255 * 0.735357)
    EXPECT_EQ(out.at(1, 0)[0], 0);
    EXPECT_EQ(out.at(1, 0)[1], 255);
}

// The table behind to_image8 gives what pow gives: on 4 million floats spread evenly over the
// bit patterns of (0, 1), on every float within 4096 steps of where each code starts (found
// from the inverse transfer function, independently of the table), and on the special values.
// (Every float of (0, 1), about 10^9, was checked once, 2026-12-03.)
// A NaN or infinite pixel is shown magenta and counted, the first named with its --debug-pixel
// command, instead of turning black (or white) in the PNG without a word.
TEST(NonFinitePixels, AreMagentaCountedAndNamed) {
    Image image(4, 3);
    for (Color& c : image.pixels) c = Color(0.25f);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    image.pixels[6] = Color(0.5f, nan, 0.5f);  // x 2, y 1
    image.pixels[11] = Color(inf, 0, 0);
    const NonFinitePixels found = mark_non_finite_pixels(image);
    EXPECT_EQ(found.count, 2);
    EXPECT_EQ(found.first_x, 2);
    EXPECT_EQ(found.first_y, 1);
    EXPECT_EQ(image.pixels[6], Color(1, 0, 1));
    EXPECT_EQ(image.pixels[11], Color(1, 0, 1));
    EXPECT_EQ(image.pixels[0], Color(0.25f)) << "finite pixels stay";
    const std::string line = found.describe("s.json");
    EXPECT_NE(line.find("s.json: 2 pixels are not a number or infinite"), std::string::npos)
        << line;
    EXPECT_NE(line.find("rt render s.json --debug-pixel 2,1"), std::string::npos) << line;
}

TEST(Srgb, TableIsThePowEncoding) {
    const auto by_pow = [](float x) { return int(std::lround(linear_to_srgb(x) * 255)); };
    const std::uint32_t one = std::bit_cast<std::uint32_t>(1.0f);
    int wrong = 0;
    const auto check = [&](std::uint32_t bits) {
        const float x = std::bit_cast<float>(bits);
        if (encode_srgb8(x) != by_pow(x) && ++wrong <= 5)
            ADD_FAILURE() << "x = " << x << ": table " << int(encode_srgb8(x)) << ", pow "
                          << by_pow(x);
    };
    for (std::uint32_t bits = 0; bits <= one; bits += 251) check(bits);
    for (int k = 1; k <= 255; ++k) {
        const std::uint32_t start = std::bit_cast<std::uint32_t>(srgb_to_linear((k - 0.5f) / 255));
        for (std::uint32_t bits = start - 4096; bits <= std::min(start + 4096, one); ++bits)
            check(bits);
    }
    EXPECT_EQ(wrong, 0);
    for (float x : {-1.0f, -0.0f, 0.0f, 1.0f, 2.0f, 1e30f, std::nanf(""),
                    std::numeric_limits<float>::infinity()})
        EXPECT_EQ(encode_srgb8(x), x >= 1 ? 255 : by_pow(x)) << x;
}

TEST(ImageFiles, PngRoundTripIsExact) {
    const Image8 img = gradient(19, 7);
    const auto file = temp_file("roundtrip.png");
    write_image8(img, file);
    const Image8 back = read_image8(file);
    ASSERT_EQ(back.width, 19);
    ASSERT_EQ(back.height, 7);
    EXPECT_EQ(back.data, img.data);
}

TEST(ImageFiles, ExrIsWritten) {
    Image img(4, 2, Color(0.25f, 2.0f, 0.0f));
    const auto file = temp_file("linear.exr");
    write_image(img, file);
    EXPECT_GT(std::filesystem::file_size(file), 0u);
}

TEST(ImageFiles, ExrReadsBackLinearValuesExactly) {
    Image img(3, 2, Color(0.25f, 2.0f, 0.0f));
    img.at(2, 1) = Color(17.5f, 0.001f, 1e-6f);
    const auto file = temp_file("linear-back.exr");
    write_image(img, file);
    const Image back = read_image(file);  // float data is never sRGB-decoded
    ASSERT_EQ(back.width, 3);
    ASSERT_EQ(back.height, 2);
    EXPECT_EQ(back.at(0, 0), img.at(0, 0));
    EXPECT_EQ(back.at(2, 1), img.at(2, 1));
}

TEST(ImageFiles, IntegerImagesDecodeAsColorOrData) {
    // 8-bit: mid grey 188 is linear ~0.5 as colour, 188/255 as data.
    Image8 img{2, 1, {188, 188, 188, 255, 0, 0}};
    const auto file = temp_file("grey.png");
    write_image8(img, file);
    const Image color = read_image(file, Encoding::Srgb);
    const Image data = read_image(file, Encoding::Data);
    EXPECT_NEAR(color.at(0, 0).r, srgb_to_linear(188 / 255.0f), 1e-6f);
    EXPECT_NEAR(data.at(0, 0).r, 188 / 255.0f, 1e-6f);
    EXPECT_FLOAT_EQ(data.at(1, 0).r, 1.0f);
    EXPECT_FLOAT_EQ(data.at(1, 0).g, 0.0f);
    // 16-bit PNG: read at full precision (a data texture keeps 1/65535 steps).
    const auto wide = temp_file("wide.png");
    {  // written by libpng's own simplified API, independently of the reader under test
        png_image out{};
        out.version = PNG_IMAGE_VERSION;
        out.width = 2;
        out.height = 1;
        out.format = PNG_FORMAT_LINEAR_Y;  // 16-bit grey
        const png_uint_16 px[2] = {1, 65535};
        ASSERT_TRUE(png_image_write_to_file(&out, wide.c_str(), 0, px, 0, nullptr)) << out.message;
    }
    const Image grey = read_image(wide, Encoding::Data);
    EXPECT_NEAR(grey.at(0, 0).r, 1 / 65535.0f, 1e-9f);
    EXPECT_EQ(grey.at(0, 0).g, grey.at(0, 0).r);  // grey spread to three channels
    EXPECT_FLOAT_EQ(grey.at(1, 0).b, 1.0f);
}

TEST(ImageFiles, ReadImageErrorsNameTheFile) {
    const auto junk = temp_file("junk2.exr");
    std::ofstream(junk) << "not an image";
    try {
        read_image(junk);
        FAIL();
    } catch (const ImageError& e) {
        EXPECT_NE(std::string(e.what()).find("junk2.exr"), std::string::npos) << e.what();
    }
    EXPECT_THROW(read_image(temp_file("missing.exr")), ImageError);
}

TEST(ImageFiles, ClearErrors) {
    EXPECT_THROW(read_image8(temp_file("does-not-exist.png")), ImageError);
    const auto junk = temp_file("junk.png");
    std::ofstream(junk) << "this is not a png";
    EXPECT_THROW(read_image8(junk), ImageError);
    EXPECT_THROW(write_image(Image(2, 2), temp_file("x.bmpx")), ImageError);
    try {
        write_image(Image(2, 2), temp_file("x.txt"));
        FAIL();
    } catch (const ImageError& e) {
        EXPECT_NE(std::string(e.what()).find("x.txt"), std::string::npos) << e.what();
    }
}

// A damaged or hostile header must not cost gigabytes: the size is refused before the pixels
// are allocated, in one line naming the file.
TEST(ImageFiles, HugePngHeaderIsRefusedBeforeDecoding) {
    const auto file = temp_file("huge.png");
    write_image8(gradient(4, 4), file);
    std::string bytes;
    {
        std::ifstream in(file, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    // IHDR data starts at byte 16 (signature 8, length 4, type 4): width, height big-endian.
    const std::uint32_t side = 100000;
    for (int k = 0; k < 2; ++k)
        for (int b = 0; b < 4; ++b) bytes[16 + 4 * k + b] = char((side >> (24 - 8 * b)) & 0xff);
    const std::uint32_t crc =
        std::uint32_t(crc32(0, reinterpret_cast<const unsigned char*>(bytes.data()) + 12, 4 + 13));
    for (int b = 0; b < 4; ++b) bytes[29 + b] = char((crc >> (24 - 8 * b)) & 0xff);
    std::ofstream(file, std::ios::binary) << bytes;
    try {
        read_image(file);
        FAIL() << "a 100000 x 100000 header was accepted";
    } catch (const ImageError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("huge.png: error: the image is 100000 x 100000 pixels"),
                  std::string::npos)
            << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
}

TEST(ImageFiles, TruncatedPngNamesTheFile) {
    const auto file = temp_file("truncated.png");
    write_image8(gradient(64, 64), file);
    std::filesystem::resize_file(file, std::filesystem::file_size(file) / 2);
    try {
        read_image8(file);
        FAIL() << "a truncated PNG was read";
    } catch (const ImageError& e) {
        EXPECT_NE(std::string(e.what()).find("truncated.png: error: cannot decode the PNG"),
                  std::string::npos)
            << e.what();
    }
}

// Formats beyond PNG and EXR come through the OpenImageIO plug-in (image/oiio_plugin.h): here a
// Radiance HDR file of two flat RGBE pixels, written byte by byte.
TEST(ImageFiles, RadianceHdrIsReadThroughOpenImageIO) {
    const auto file = temp_file("two.hdr");
    {
        std::ofstream out(file, std::ios::binary);
        out << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n";
        // RGBE: value = mantissa * 2^(exponent - 136).
        const unsigned char pixels[8] = {128, 64, 32, 129, 128, 128, 128, 140};
        out.write(reinterpret_cast<const char*>(pixels), sizeof pixels);
    }
    const Image image = read_image(file);  // float data: never sRGB-decoded
    ASSERT_EQ(image.width, 2);
    ASSERT_EQ(image.height, 1);
    EXPECT_NEAR(image.at(0, 0).r, 1.0f, 0.01f);
    EXPECT_NEAR(image.at(0, 0).g, 0.5f, 0.01f);
    EXPECT_NEAR(image.at(0, 0).b, 0.25f, 0.01f);
    EXPECT_NEAR(image.at(1, 0).g, 2048.0f, 20.0f);  // 128 * 2^4
}

// Every file of framework/tests/bad_images (expected.txt: file | part of the message) gives one
// line naming the file and what is wrong, never a crash or a huge allocation.
TEST(ImageFiles, DamagedFilesGiveOneLineErrors) {
    const auto dir = source_dir() / "framework/tests/bad_images";
    std::ifstream list(dir / "expected.txt");
    ASSERT_TRUE(list) << dir / "expected.txt";
    int checked = 0;
    for (std::string line; std::getline(list, line);) {
        if (line.empty() || line[0] == '#') continue;
        const std::size_t bar = line.find(" | ");
        ASSERT_NE(bar, std::string::npos) << line;
        const std::string name = line.substr(0, bar), part = line.substr(bar + 3);
        SCOPED_TRACE(name);
        try {
            read_image(dir / name);
            ADD_FAILURE() << "read without an error";
        } catch (const ImageError& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find(name + ": error: "), std::string::npos) << what;
            EXPECT_NE(what.find(part), std::string::npos) << what;
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        }
        ++checked;
    }
    EXPECT_GE(checked, 13);
}

// Damaged headers of valid PNG and EXR files (bytes flipped, files cut short), 400 of each at a
// fixed seed: every one is read or refused with an ImageError; none crashes.
TEST(ImageFiles, FuzzedHeadersAreReadOrRefused) {
    Image image(5, 3, Color(0.25f, 0.5f, 1.0f));
    for (const char* name : {"fuzz-seed.png", "fuzz-seed.exr"}) {
        const auto seed_file = temp_file(name);
        write_image(image, seed_file);
        std::string bytes;
        {
            std::ifstream in(seed_file, std::ios::binary);
            bytes.assign(std::istreambuf_iterator<char>(in), {});
        }
        SplitMix64 random(std::string(name).ends_with(".png") ? 1 : 2);
        int refused = 0;
        for (int round = 0; round < 400; ++round) {
            std::string damaged = bytes;
            const std::size_t header = std::min<std::size_t>(damaged.size(), 96);
            const int flips = 1 + int(random.next() % 4);
            for (int f = 0; f < flips; ++f)
                damaged[random.next() % header] = char(random.next() & 0xff);
            if (random.next() % 4 == 0) damaged.resize(random.next() % damaged.size());
            const auto file = temp_file(std::string("fuzz-") + name);
            std::ofstream(file, std::ios::binary) << damaged;
            try {
                const Image back = read_image(file);
                EXPECT_GT(back.width, 0);
            } catch (const ImageError& e) {
                ++refused;
                EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
            }
        }
        EXPECT_GT(refused, 0) << name << ": the damage should be noticed at least once";
    }
}

TEST(Compare, IdenticalImagesMatch) {
    const Image8 a = gradient(10, 10);
    const CompareResult r = compare_images(a, a);
    EXPECT_TRUE(r.passed);
    EXPECT_EQ(r.max_difference, 0);
    EXPECT_EQ(r.failing_pixels, 0);
}

// Differences within the tolerance pass; one pixel over it out of 10,000 is 0.01% and passes
// the 0.1% budget; 11 such pixels (0.11%) fail.
TEST(Compare, ToleranceAndFailingPercentage) {
    const Image8 ref = gradient(100, 100);
    Image8 img = ref;
    for (auto& v : img.data) v = std::uint8_t(std::min(255, v + 2));
    EXPECT_TRUE(compare_images(img, ref).passed);
    img.at(50, 50)[1] = std::uint8_t(ref.at(50, 50)[1] + 40);
    CompareResult r = compare_images(img, ref);
    EXPECT_TRUE(r.passed) << r.summary();
    EXPECT_EQ(r.failing_pixels, 1);
    for (int i = 0; i < 10; ++i) img.at(i, 0)[2] = 0;
    r = compare_images(img, ref);
    EXPECT_FALSE(r.passed) << r.summary();
    EXPECT_EQ(r.failing_pixels, 11);
    EXPECT_EQ(std::max(r.heat_map.at(50, 50)[0], r.heat_map.at(50, 50)[2]), 255)
        << "a failing pixel is at full strength (red or blue by its sign)";
}

// The summary says which way an image is off, and the heat map shows it: red where brighter than
// the reference, blue where darker.
TEST(Compare, SaysBrighterOrDarkerAndShowsIt) {
    const Image8 ref = gradient(20, 10);
    Image8 dark = ref;
    for (std::uint8_t& v : dark.data) v = std::uint8_t(v / 2);
    CompareResult r = compare_images(dark, ref);
    EXPECT_LT(r.mean_signed_difference, 0);
    EXPECT_NE(r.summary().find("yours is darker than the reference by"), std::string::npos)
        << r.summary();
    EXPECT_EQ(r.heat_map.at(19, 9)[2], 255) << "a failing darker pixel is full blue";
    EXPECT_EQ(r.heat_map.at(19, 9)[0], 0);
    Image8 bright = ref;
    bright.at(19, 9)[0] = 255;
    r = compare_images(bright, ref);
    EXPECT_GT(r.mean_signed_difference, 0);
    EXPECT_EQ(r.heat_map.at(19, 9)[0], 255) << "a failing brighter pixel is full red";
    EXPECT_NE(r.summary().find("brighter than the reference"), std::string::npos) << r.summary();
    Image8 both = ref;
    both.at(0, 0)[0] = std::uint8_t(ref.at(0, 0)[0] + 50);
    both.at(10, 0)[0] = std::uint8_t(ref.at(10, 0)[0] - 50);
    EXPECT_NE(compare_images(both, ref).summary().find("as much brighter as darker"),
              std::string::npos);
}

TEST(Compare, SizeMismatchFails) {
    const CompareResult r = compare_images(gradient(10, 10), gradient(10, 11));
    EXPECT_FALSE(r.passed);
    EXPECT_FALSE(r.size_matches);
}

// A one-pixel shift of a hard edge fails pixel-wise but passes with the 3x3 neighbourhood.
TEST(Compare, NeighbourhoodForgivesShiftedEdges) {
    Image8 ref{20, 20, std::vector<std::uint8_t>(20 * 20 * 3, 0)};
    Image8 img = ref;
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 20; ++x) {
            if (x >= 10) std::fill_n(ref.at(x, y), 3, 255);
            if (x >= 11) std::fill_n(img.at(x, y), 3, 255);
        }
    EXPECT_FALSE(compare_images(img, ref).passed);
    CompareOptions forgiving;
    forgiving.neighbourhood = true;
    EXPECT_TRUE(compare_images(img, ref, forgiving).passed);
}

}  // namespace
}  // namespace rt
