// The accuracy lab's texture-filter experiment (issue 13): a checkerboard floor seen at a
// grazing angle, as stages/07-textures/scenes/filtering.json, looked up per pixel by nearest,
// bilinear and OpenImageIO's TextureSystem (trilinear, anisotropic), against a 16 x 16
// supersampled bilinear reference. The lookups are the bench's own copies (no student code);
// OpenImageIO comes through the framework's dlopen'd module, as `rt render --texture-filter oiio`.
#include "bench/texture_filters.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/source_dir.h"
#include "image/image.h"
#include "image/oiio_loader.h"

namespace rt::bench {
namespace {

using Clock = std::chrono::steady_clock;

// The texture: stored sRGB values, decoded per texel before filtering (as stage 07 does).
struct Texels {
    int w = 0, h = 0;
    std::vector<Color> linear;
    const Color& at(int i, int j) const {
        // repeat
        i = ((i % w) + w) % w;
        j = ((j % h) + h) % h;
        return linear[std::size_t(j) * w + i];
    }
};

Color nearest(const Texels& t, double u, double v) {
    return t.at(int(std::floor(std::fmod(u * t.w, 2.0 * t.w))),
                int(std::floor(std::fmod(v * t.h, 2.0 * t.h))));
}

Color bilinear(const Texels& t, double u, double v) {
    const double x = std::fmod(u * t.w, 2.0 * t.w) - 0.5, y = std::fmod(v * t.h, 2.0 * t.h) - 0.5;
    const double x0 = std::floor(x), y0 = std::floor(y);
    const float fx = float(x - x0), fy = float(y - y0);
    const int i = int(x0), j = int(y0);
    const Color top = (1 - fx) * t.at(i, j) + fx * t.at(i + 1, j);
    const Color bottom = (1 - fx) * t.at(i, j + 1) + fx * t.at(i + 1, j + 1);
    return (1 - fy) * top + fy * bottom;
}

// The camera and floor of filtering.json: eye (0, 1.2, 6) looking at (0, 0, -10), 50 degrees
// vertical, the floor y = -1, one image every 4 units (slot scale 0.25 per world unit).
struct View {
    int width, height;
    double eye[3] = {0, 1.2, 6};
    double f[3], r[3], u[3];  // forward, right, up (unit)
    double tan_half;

    View(int w, int h) : width(w), height(h), tan_half(std::tan(25.0 * 3.14159265358979 / 180)) {
        double d[3] = {0 - eye[0], 0 - eye[1], -10 - eye[2]};
        const double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        for (int k = 0; k < 3; ++k) f[k] = d[k] / n;
        // right = normalize(f x (0, 1, 0)), up = r x f
        r[0] = -f[2];
        r[1] = 0;
        r[2] = f[0];
        const double rn = std::sqrt(r[0] * r[0] + r[2] * r[2]);
        r[0] /= rn;
        r[2] /= rn;
        u[0] = r[1] * f[2] - r[2] * f[1];
        u[1] = r[2] * f[0] - r[0] * f[2];
        u[2] = r[0] * f[1] - r[1] * f[0];
    }
    // Texture coordinates where the ray through image point (px, py) meets the floor; false
    // when it looks above the horizon.
    bool uv(double px, double py, double& s, double& t) const {
        const double aspect = double(width) / height;
        const double x = (2 * px / width - 1) * tan_half * aspect,
                     y = (1 - 2 * py / height) * tan_half;
        double d[3];
        for (int k = 0; k < 3; ++k) d[k] = f[k] + x * r[k] + y * u[k];
        if (d[1] >= 0) return false;
        const double hit = (-1 - eye[1]) / d[1];
        s = (eye[0] + hit * d[0]) * 0.25;
        t = (eye[2] + hit * d[2]) * 0.25;
        return true;
    }
};

const Color kSky(0.55f, 0.7f, 0.9f);

std::uint8_t encode(float linear) {
    return std::uint8_t(std::lround(255 * linear_to_srgb(std::clamp(linear, 0.0f, 1.0f))));
}

// The reference: 16 x 16 stratified bilinear samples per pixel, box-filtered.
std::vector<Color> reference_image(const Texels& tex, const View& view) {
    std::vector<Color> reference(std::size_t(view.width) * view.height);
    for (int y = 0; y < view.height; ++y)
        for (int x = 0; x < view.width; ++x) {
            Color sum(0);
            for (int sy = 0; sy < 16; ++sy)
                for (int sx = 0; sx < 16; ++sx) {
                    double s, t;
                    sum += view.uv(x + (sx + 0.5) / 16, y + (sy + 0.5) / 16, s, t)
                               ? bilinear(tex, s, t)
                               : kSky;
                }
            reference[std::size_t(y) * view.width + x] = sum / 256.0f;
        }
    return reference;
}

// One filter's point: its image (one lookup a pixel, with the footprint from the neighbouring
// pixels' points, as ray differentials give it), timed, and its error against the reference.
struct Scorer {
    const View& view;
    const std::vector<Color>& reference;

    template <typename Lookup>
    TexturePoint operator()(const std::string& name, Lookup&& lookup) const {
        const int width = view.width, height = view.height;
        const std::size_t n = reference.size();
        std::vector<Color> image(n);
        const auto start = Clock::now();
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                double s, t, s1, t1, s2, t2;
                if (!view.uv(x + 0.5, y + 0.5, s, t)) {
                    image[std::size_t(y) * width + x] = kSky;
                    continue;
                }
                // A neighbour above the horizon gives no footprint in its direction.
                if (!view.uv(x + 1.5, y + 0.5, s1, t1)) {
                    s1 = s;
                    t1 = t;
                }
                if (!view.uv(x + 0.5, y + 1.5, s2, t2)) {
                    s2 = s;
                    t2 = t;
                }
                image[std::size_t(y) * width + x] = lookup(s, t, s1 - s, t1 - t, s2 - s, t2 - t);
            }
        const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        double squared = 0;
        long off = 0;
        for (std::size_t i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c) {
                const int diff = int(encode(image[i][c])) - int(encode(reference[i][c]));
                squared += double(diff) * diff;
                if (c == 0 && std::abs(diff) > 2) ++off;
            }
        return TexturePoint{name, ms, std::sqrt(squared / double(3 * n)), 100.0 * off / double(n)};
    }
};

// OpenImageIO's trilinear and anisotropic lookups through the module; without it, `note` says
// why the rows are missing instead of failing the run.
void add_oiio_points(const Texels& tex, const Scorer& score, std::vector<TexturePoint>& points,
                     std::string& note) {
    const image_files::OiioPlugin& plugin = image_files::oiio_plugin();
    if (!plugin.textures_create) {
        note = "OpenImageIO rows missing: " + plugin.problem;
        return;
    }
    char error[512] = {};
    RtOiioTextures* system = plugin.textures_create(error, sizeof error);
    if (!system) {
        note = std::string("OpenImageIO rows missing: ") + error;
        return;
    }
    const auto mip_start = Clock::now();
    std::vector<float> rgb;
    for (const Color& c : tex.linear) rgb.insert(rgb.end(), {c.r, c.g, c.b});
    const int index = plugin.textures_add(system, rgb.data(), tex.w, tex.h, error, sizeof error);
    const double mip_ms =
        std::chrono::duration<double, std::milli>(Clock::now() - mip_start).count();
    if (index < 0) {
        plugin.textures_destroy(system);
        note = std::string("OpenImageIO rows missing: ") + error;
        return;
    }
    for (int aniso : {0, 16}) {
        points.push_back(score(
            aniso ? "OIIO anisotropic (16)" : "OIIO trilinear",
            [&](double s, double t, double dsdx, double dtdx, double dsdy, double dtdy) {
                float out[3];
                plugin.textures_lookup(system, index, 0, aniso, float(s), float(t), float(dsdx),
                                       float(dtdx), float(dsdy), float(dtdy), out);
                return Color(out[0], out[1], out[2]);
            }));
    }
    plugin.textures_destroy(system);
    note = "OpenImageIO's mip-map pyramid took " + std::to_string(int(std::lround(mip_ms))) +
           " ms to build (not in the lookup times)";
}

}  // namespace

std::vector<TexturePoint> measure_texture_filters(int width, int height, std::string& note) {
    const Image stored = read_image(
        source_dir() / "stages/07-textures/scenes/textures/fine_checks.png", Encoding::Data);
    Texels tex{stored.width, stored.height, {}};
    for (const Color& c : stored.pixels)
        tex.linear.push_back(Color(srgb_to_linear(c.r), srgb_to_linear(c.g), srgb_to_linear(c.b)));
    const View view(width, height);
    const std::vector<Color> reference = reference_image(tex, view);
    const Scorer score{view, reference};
    std::vector<TexturePoint> points;
    points.push_back(score("nearest", [&](double s, double t, double, double, double, double) {
        return nearest(tex, s, t);
    }));
    points.push_back(score("bilinear", [&](double s, double t, double, double, double, double) {
        return bilinear(tex, s, t);
    }));
    add_oiio_points(tex, score, points, note);
    return points;
}

}  // namespace rt::bench
