// Stage 07 tests: procedural textures. Checkerboards at chosen cells, gradient noise's defining
// properties (zero at lattice points, continuous, bounded, deterministic, not constant) and
// marble's range, at fixed points: any correct implementation passes.
#include <cmath>

#include "stage_api/stage07.h"
#include "testing/stage_test.h"

namespace rt {
namespace {

RT_TEST_SUITE(Checker, "checkerboards");
RT_TEST_SUITE(Noise, "gradient-noise");
RT_TEST_SUITE(Marble, "marble");

const Color kA(1, 0, 0), kB(0, 0, 1);

TEST_F(Checker, TwoDimensional) {
    EXPECT_EQ(checker_2d(Vec2(0.5f, 0.5f), kA, kB), kA) << "square (0, 0) is a";
    EXPECT_EQ(checker_2d(Vec2(1.5f, 0.5f), kA, kB), kB) << "square (1, 0) is b";
    EXPECT_EQ(checker_2d(Vec2(1.5f, 1.5f), kA, kB), kA) << "square (1, 1) is a";
    EXPECT_EQ(checker_2d(Vec2(-0.5f, 0.5f), kA, kB), kB)
        << "square (-1, 0) is b: floor, not truncation";
    EXPECT_EQ(checker_2d(Vec2(-0.5f, -0.5f), kA, kB), kA) << "square (-1, -1) is a";
    EXPECT_EQ(checker_2d(Vec2(1, 0), kA, kB), kB) << "an edge belongs to the square above it";
}

TEST_F(Checker, ThreeDimensional) {
    EXPECT_EQ(checker_3d(Vec3(0.1f, 0.1f, 0.1f), kA, kB, 1), kA);
    EXPECT_EQ(checker_3d(Vec3(1.1f, 0.1f, 0.1f), kA, kB, 1), kB);
    EXPECT_EQ(checker_3d(Vec3(1.1f, 1.1f, 0.1f), kA, kB, 1), kA);
    EXPECT_EQ(checker_3d(Vec3(1.1f, 1.1f, 1.1f), kA, kB, 1), kB);
    EXPECT_EQ(checker_3d(Vec3(-0.1f, 0.1f, 0.1f), kA, kB, 1), kB) << "floor for negatives";
    EXPECT_EQ(checker_3d(Vec3(0.3f, 0.1f, 0.1f), kA, kB, 0.25f), kB) << "cubes of side 0.25";
}

TEST_F(Checker, PeriodicAndDeterministic) {
    for (int i = 0; i < 50; ++i) {
        const Vec2 uv(Real(i) * 0.37f - 7, Real(i) * 0.61f - 9);
        EXPECT_EQ(checker_2d(uv, kA, kB), checker_2d(uv + Vec2(2, 0), kA, kB)) << "period 2 in u";
        EXPECT_EQ(checker_2d(uv, kA, kB), checker_2d(uv + Vec2(0, 2), kA, kB)) << "period 2 in v";
        EXPECT_NE(checker_2d(uv, kA, kB), checker_2d(uv + Vec2(1, 0), kA, kB))
            << "neighbours differ";
        const Vec3 p(Real(i) * 0.13f, Real(i) * 0.29f - 2, 1.5f - Real(i) * 0.07f);
        EXPECT_EQ(checker_3d(p, kA, kB, 0.5f), checker_3d(p + Vec3(0, 0, 1), kA, kB, 0.5f))
            << "period 2 size";
    }
}

TEST_F(Noise, Deterministic) {
    const Vec3 p(1.23f, -4.56f, 7.89f);
    EXPECT_EQ(gradient_noise(p), gradient_noise(p)) << "the same point, the same value";
    EXPECT_EQ(marble(p, kA, kB, 1), marble(p, kA, kB, 1));
}

TEST_F(Noise, ZeroAtLatticePoints) {
    for (int x = -2; x <= 2; ++x)
        for (int y = -2; y <= 2; ++y)
            EXPECT_NEAR(gradient_noise(Vec3(Real(x), Real(y), 3)), 0, 1e-6)
                << "at lattice point (" << x << ", " << y << ", 3)";
}

TEST_F(Noise, MatchesTheGradientsNearACorner) {
    // Close to a corner c, noise(c + d) ~ g(c).d (the fade curve is flat there: weight 1 - O(d^3)).
    const Vec3 d(0.01f, -0.02f, 0.015f);
    for (int x = 0; x < 3; ++x) {
        const Vec3 c(Real(x), 1, -2);
        const Real expected = glm::dot(noise_gradient(x, 1, -2), d);
        EXPECT_NEAR(gradient_noise(c + d), expected, 2e-4)
            << "near corner (" << x
            << ", 1, -2): there the noise must be g(c).d, the other "
               "corners' weights vanishing as the fade curve 6t^5 - 15t^4 + 10t^3 does";
    }
}

TEST_F(Noise, ContinuousBoundedAndNotConstant) {
    Real lowest = 1, highest = -1;
    for (int i = 0; i < 400; ++i) {
        const Vec3 p(Real(i) * 0.173f, Real(i) * 0.071f - 3, Real(i) * 0.031f + 0.5f);
        const Real n = gradient_noise(p);
        EXPECT_LE(std::abs(n), 1) << "at sample " << i;
        // A tiny step changes the value a little: no jumps at cell borders.
        EXPECT_NEAR(gradient_noise(p + Vec3(1e-3f, 0, 0)), n, 1e-2) << "jump near sample " << i;
        lowest = std::min(lowest, n);
        highest = std::max(highest, n);
    }
    EXPECT_GT(highest - lowest, 0.5f) << "noise over 400 points should vary";
}

TEST_F(Marble, BetweenItsColorsAndVaried) {
    Real reds = 0, blues = 0;
    for (int i = 0; i < 200; ++i) {
        const Color c = marble(Vec3(Real(i) * 0.05f, 0.3f, 0.7f), kA, kB, 1);
        EXPECT_NEAR(c.r + c.b, 1, 1e-5) << "a mix of a and b at sample " << i;
        EXPECT_GE(c.r, -1e-6f);
        EXPECT_GE(c.b, -1e-6f);
        reds += c.r;
        blues += c.b;
    }
    EXPECT_GT(reds, 20) << "veins of both colours";
    EXPECT_GT(blues, 20) << "veins of both colours";
}

TEST_F(Marble, ScaleStretchesThePattern) {
    const Vec3 p(0.37f, 0.21f, 0.9f);
    const Color small = marble(p, kA, kB, 1), big = marble(p * Real(2), kA, kB, 2);
    EXPECT_NEAR(small.r, big.r, 1e-5) << "marble(2p, scale 2) = marble(p, scale 1)";
}

TEST_F(Marble, FollowsTheTurbulenceFormula) {
    // s = 0.5 + 0.5 sin((x + 4 turbulence(p)) pi), turbulence = sum over k = 0..4 of
    // |noise(2^k p)| / 2^k; with a = red and b = blue, s is the blue channel.
    for (int i = 0; i < 20; ++i) {
        const Vec3 point(Real(i) * 0.37f - 3, Real(i) * 0.11f + 0.2f, 1.3f - Real(i) * 0.05f);
        const Real scale = 1.5f;
        const Vec3 p = point / scale;
        Real turbulence = 0;
        for (int k = 0; k < 5; ++k)
            turbulence += std::abs(gradient_noise(p * Real(1 << k))) / Real(1 << k);
        const Real s = Real(0.5) + Real(0.5) * std::sin((p.x + 4 * turbulence) * kPi);
        EXPECT_NEAR(marble(point, kA, kB, scale).b, s, 1e-4)
            << "sample " << i
            << ": marble's turbulence sums |noise(2^k p)| / 2^k, each octave "
               "twice the frequency and half the weight of the last";
    }
}

}  // namespace
}  // namespace rt
