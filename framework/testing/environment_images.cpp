#include "testing/environment_images.h"

#include <cmath>
#include <string>

#include "scene/environment.h"

namespace rt::testing {

namespace {

// 5x7 glyphs of the face names, one string a row, '#' set.
struct Glyph {
    char c;
    const char* rows[7];
};
constexpr Glyph kGlyphs[] = {
    {'+', {".....", "..#..", "..#..", "#####", "..#..", "..#..", "....."}},
    {'-', {".....", ".....", ".....", "#####", ".....", ".....", "....."}},
    {'X', {"#...#", "#...#", ".#.#.", "..#..", ".#.#.", "#...#", "#...#"}},
    {'Y', {"#...#", "#...#", ".#.#.", "..#..", "..#..", "..#..", "..#.."}},
    {'Z', {"#####", "....#", "...#.", "..#..", ".#...", "#....", "#####"}},
};

// Draws `c` twice the glyph size with its top-left corner at (x, y).
void draw_glyph(Image& image, char c, int x, int y, const Color& ink) {
    for (const Glyph& g : kGlyphs) {
        if (g.c != c) continue;
        for (int j = 0; j < 14; ++j)
            for (int i = 0; i < 10; ++i)
                if (g.rows[j / 2][i / 2] == '#') image.at(x + i, y + j) = ink;
    }
}

}  // namespace

Image make_latlong_sky() {
    const int w = 64, h = 32;
    Image sky(w, h);
    const Color zenith(0.15f, 0.3f, 0.75f), horizon(0.75f, 0.82f, 0.9f);
    const Color markers[4] = {
        {0.9f, 0.1f, 0.1f}, {0.1f, 0.8f, 0.1f}, {0.1f, 0.2f, 0.95f}, {0.95f, 0.85f, 0.1f}};
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const float u = (float(i) + 0.5f) / float(w), v = (float(j) + 0.5f) / float(h);
            Color c;
            if (v < 0.5f) {
                const float t = v / 0.5f;  // 0 at the zenith, 1 at the horizon
                c = zenith * (1 - t * t) + horizon * (t * t);
            } else {
                c = ((i / 4 + j / 4) % 2 == 0) ? Color(0.2f, 0.16f, 0.1f)
                                               : Color(0.1f, 0.14f, 0.06f);
            }
            // Markers just above the horizon (rows 12-15), centred on u = 0, 0.25, 0.5, 0.75:
            // -z red, +x green, +z blue, -x yellow (docs/conventions.md#environment-maps).
            if (j >= 12 && j < 16) {
                const int k = ((i + 2) % w) / 4;  // columns 62, 63, 0, 1 form the first marker
                if (k % 4 == 0) c = markers[k / 4];
            }
            // The sun: a disc about 4 texels across around (u, v) = (0.0625, 0.3), up and to the
            // right of -z (22.5 degrees).
            const float du = (u - 0.0625f) * float(w), dv = (v - 0.3f) * float(h);
            if (du * du + dv * dv <= 4.0f) c = Color(12.0f, 11.0f, 9.0f);
            sky.at(i, j) = c;
        }
    return sky;
}

Image make_cube_face(int face) {
    const Color colors[kCubeFaces] = {{0.8f, 0.2f, 0.2f},  {0.2f, 0.7f, 0.7f},
                                      {0.3f, 0.5f, 0.9f},  {0.45f, 0.3f, 0.15f},
                                      {0.85f, 0.8f, 0.2f}, {0.7f, 0.3f, 0.8f}};
    const int n = 32;
    Image image(n, n, colors[face]);
    const Color dark = colors[face] * 0.4f, ink(1), black(0);
    for (int k = 0; k < n; ++k)
        image.at(k, 0) = image.at(k, n - 1) = image.at(0, k) = image.at(n - 1, k) = dark;
    for (int j = 2; j < 5; ++j)  // the (u, v) = (0, 0) corner
        for (int i = 2; i < 5; ++i) image.at(i, j) = black;
    for (int j = 0; j < 6; ++j)  // an arrow to row 0: a triangle on a stem
        for (int i = 16 - j; i < 16 + j; ++i) image.at(i, 3 + j) = ink;
    for (int j = 9; j < 11; ++j) image.at(15, j) = image.at(16, j) = ink;
    const char sign = face % 2 == 0 ? '+' : '-';
    const char axis = "XYZ"[face / 2];
    draw_glyph(image, sign, 5, 13, ink);
    draw_glyph(image, axis, 17, 13, ink);
    return image;
}

void write_environment_images(const std::filesystem::path& folder) {
    std::filesystem::create_directories(folder / "cube");
    write_image(make_latlong_sky(), folder / "sky.exr");
    for (int f = 0; f < kCubeFaces; ++f)
        write_image(make_cube_face(f), folder / "cube" / (std::string(kCubeFaceNames[f]) + ".png"));
}

}  // namespace rt::testing
