// Stage 07 tests: image lookup. sRGB decoding against the standard's values, the three wrap
// modes, nearest and bilinear lookups at texel centres, edges and corners of small images whose
// every texel is known, and coordinates far outside [0, 1].
#include <cmath>
#include <vector>

#include "stage_api/stage07.h"
#include "testing/stage_test.h"

namespace rt {
namespace {

RT_TEST_SUITE(ColorSpace, "colour-spaces");
RT_TEST_SUITE(Wrap, "wrap-modes");
RT_TEST_SUITE(Nearest, "nearest-neighbour");
RT_TEST_SUITE(Bilinear, "bilinear-filtering");

void expect_color(const Color& got, const Color& want, const char* what, float tol = 1e-5f) {
    EXPECT_NEAR(got.r, want.r, tol) << what << " (red)";
    EXPECT_NEAR(got.g, want.g, tol) << what << " (green)";
    EXPECT_NEAR(got.b, want.b, tol) << what << " (blue)";
}

// A 3 x 2 image whose texel (i, j) stores (i / 4, j / 4, 0.5): every lookup can be predicted.
struct Grid {
    std::vector<Color> texels;
    TextureView view;
    Grid(int w = 3, int h = 2, bool srgb = false) {
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i) texels.push_back(Color(float(i) / 4, float(j) / 4, 0.5f));
        view = TextureView{texels.data(), w, h, srgb};
    }
};

TEST_F(ColorSpace, SrgbDecodingMatchesTheStandard) {
    EXPECT_NEAR(srgb_to_linear_value(0), 0, 1e-7);
    EXPECT_NEAR(srgb_to_linear_value(1), 1, 1e-6);
    EXPECT_NEAR(srgb_to_linear_value(0.04045f), 0.04045f / 12.92f, 1e-7) << "the linear segment";
    EXPECT_NEAR(srgb_to_linear_value(0.5f), 0.214041f, 1e-5) << "mid grey is about 0.214 linear";
    EXPECT_NEAR(srgb_to_linear_value(188.0f / 255), 0.502886f, 1e-5) << "stored 188 is half light";
    // The two pieces meet: no jump at the threshold.
    EXPECT_NEAR(srgb_to_linear_value(0.0404f), srgb_to_linear_value(0.0405f), 1e-5);
}

TEST_F(ColorSpace, ColorTexelsAreDecodedDataTexelsAreNot) {
    std::vector<Color> texels = {Color(0.5f, 1, 0)};
    const TextureView color{texels.data(), 1, 1, true}, data{texels.data(), 1, 1, false};
    expect_color(decoded_texel(color, 0, 0), Color(0.214041f, 1, 0), "sRGB texel decoded");
    expect_color(decoded_texel(data, 0, 0), Color(0.5f, 1, 0), "data texel as stored");
}

TEST_F(Wrap, RepeatClampMirror) {
    const int n = 3;
    const int repeat[] = {1, 2, 0, 1, 2, 0, 1, 2};  // i = -5 .. 2
    const int clamp[] = {0, 0, 0, 0, 0, 0, 1, 2};
    const int mirror[] = {1, 2, 2, 1, 0, 0, 1, 2};  // ... 2 1 0 | 0 1 2
    for (int i = -5; i <= 2; ++i) {
        EXPECT_EQ(wrap_texel(i, n, TextureWrap::Repeat), repeat[i + 5]) << "repeat, i = " << i;
        EXPECT_EQ(wrap_texel(i, n, TextureWrap::Clamp), clamp[i + 5]) << "clamp, i = " << i;
        EXPECT_EQ(wrap_texel(i, n, TextureWrap::Mirror), mirror[i + 5]) << "mirror, i = " << i;
    }
    EXPECT_EQ(wrap_texel(3, n, TextureWrap::Mirror), 2) << "the edge texel twice";
    EXPECT_EQ(wrap_texel(5, n, TextureWrap::Mirror), 0);
    EXPECT_EQ(wrap_texel(6, n, TextureWrap::Mirror), 0);
    EXPECT_EQ(wrap_texel(7, n, TextureWrap::Clamp), 2);
    EXPECT_EQ(wrap_texel(7, n, TextureWrap::Repeat), 1);
    EXPECT_EQ(wrap_texel(-1, 1, TextureWrap::Mirror), 0) << "a one-texel image";
}

TEST_F(Nearest, TexelSquares) {
    Grid g;
    // Texel (i, j) covers [i/3, (i+1)/3) x [j/2, (j+1)/2).
    expect_color(sample_nearest(g.view, Vec2(0.1f, 0.1f), TextureWrap::Repeat), Color(0, 0, 0.5f),
                 "top-left texel");
    expect_color(sample_nearest(g.view, Vec2(0.5f, 0.75f), TextureWrap::Repeat),
                 Color(0.25f, 0.25f, 0.5f), "middle column, bottom row (row 0 is the top)");
    expect_color(sample_nearest(g.view, Vec2(0.99f, 0.01f), TextureWrap::Repeat),
                 Color(0.5f, 0, 0.5f), "top-right texel");
    expect_color(sample_nearest(g.view, Vec2(1.0f / 3, 0.5f), TextureWrap::Repeat),
                 Color(0.25f, 0.25f, 0.5f), "an edge belongs to the texel on its right/below");
}

TEST_F(Nearest, OutsideTheImage) {
    Grid g;
    expect_color(sample_nearest(g.view, Vec2(1.1f, 0.2f), TextureWrap::Repeat), Color(0, 0, 0.5f),
                 "repeat: u = 1.1 is u = 0.1");
    expect_color(sample_nearest(g.view, Vec2(1.1f, 0.2f), TextureWrap::Clamp), Color(0.5f, 0, 0.5f),
                 "clamp: the right edge");
    expect_color(sample_nearest(g.view, Vec2(1.1f, 0.2f), TextureWrap::Mirror),
                 Color(0.5f, 0, 0.5f), "mirror: the right column again");
    expect_color(sample_nearest(g.view, Vec2(-0.1f, -0.1f), TextureWrap::Repeat),
                 Color(0.5f, 0.25f, 0.5f), "repeat: negative coordinates wrap to the far side");
    // Far away coordinates (a big uv scale) must not overflow or crash.
    const Color far = sample_nearest(g.view, Vec2(3e9f, -3e9f), TextureWrap::Repeat);
    EXPECT_FALSE(std::isnan(far.r)) << "uv = (3e9, -3e9)";
    const Color clamped = sample_nearest(g.view, Vec2(3e9f, -3e9f), TextureWrap::Clamp);
    expect_color(clamped, Color(0.5f, 0, 0.5f), "clamp far away: the top-right corner");
}

TEST_F(Nearest, DecodesSrgb) {
    Grid g(3, 2, true);
    expect_color(sample_nearest(g.view, Vec2(0.5f, 0.75f), TextureWrap::Repeat),
                 Color(float(srgb_to_linear_value(0.25f)), float(srgb_to_linear_value(0.25f)),
                       float(srgb_to_linear_value(0.5f))),
                 "every channel decoded", 1e-5f);
}

TEST_F(Bilinear, ExactAtTexelCenters) {
    Grid g;
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 3; ++i) {
            const Vec2 center((i + Real(0.5)) / 3, (j + Real(0.5)) / 2);
            expect_color(sample_bilinear(g.view, center, TextureWrap::Clamp), g.view.stored(i, j),
                         "at a texel centre the texel itself");
        }
}

TEST_F(Bilinear, WeightsByDistance) {
    Grid g;
    // Halfway between the centres of texels (0, 0) and (1, 0), a quarter down to row 1.
    const Vec2 uv(Real(1) / 3, Real(0.25) + Real(0.25) * Real(0.5));
    expect_color(sample_bilinear(g.view, uv, TextureWrap::Clamp), Color(0.125f, 0.0625f, 0.5f),
                 "weights 1/2 in u and 3/4, 1/4 in v");
}

TEST_F(Bilinear, EdgesFollowTheWrapMode) {
    Grid g;
    // At u = 0 the four texels straddle the left edge: column -1 and column 0.
    const Vec2 uv(0, Real(0.25));
    expect_color(sample_bilinear(g.view, uv, TextureWrap::Clamp), Color(0, 0, 0.5f),
                 "clamp: column 0 twice");
    expect_color(sample_bilinear(g.view, uv, TextureWrap::Repeat), Color(0.25f, 0, 0.5f),
                 "repeat: halfway between the last and the first column");
    expect_color(sample_bilinear(g.view, uv, TextureWrap::Mirror), Color(0, 0, 0.5f),
                 "mirror: column 0 mirrored onto itself");
}

TEST_F(Bilinear, ReproducesALinearRamp) {
    // Stored values 0, 1/3, 2/3, 1 (data): between the first and last texel centres, bilinear
    // filtering is exact linear interpolation, whatever the position.
    std::vector<Color> ramp;
    for (int i = 0; i < 4; ++i) ramp.push_back(Color(float(i) / 3, 0.5f, 1 - float(i) / 3));
    const TextureView view{ramp.data(), 4, 1, false};
    for (int k = 0; k <= 12; ++k) {
        const Real u = Real(0.125) + Real(k) * Real(0.75 / 12);  // centre of texel 0 to texel 3
        const float expected = float((u * 4 - Real(0.5)) / 3);
        expect_color(sample_bilinear(view, Vec2(u, 0.5f), TextureWrap::Clamp),
                     Color(expected, 0.5f, 1 - expected), "on the ramp", 2e-6f);
    }
}

TEST_F(Bilinear, DecodesEachTexelBeforeWeighting) {
    std::vector<Color> texels = {Color(0), Color(1)};
    const TextureView view{texels.data(), 2, 1, true};
    // Halfway: the mean of the decoded values (0.5), not the decoding of the mean (0.214).
    expect_color(sample_bilinear(view, Vec2(0.5f, 0.5f), TextureWrap::Clamp), Color(0.5f),
                 "decode, then interpolate");
}

}  // namespace
}  // namespace rt
