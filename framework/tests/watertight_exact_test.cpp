// The framework's reference triangle test (framework/geometry/watertight.cpp) against exact
// rational arithmetic. It exercises no student code, so it lives with the framework's tests.
#include <gtest/gtest.h>

#include <cstdio>

#include "geometry/watertight.h"
#include "testing/exact_reference.h"

namespace rt {
namespace {

using namespace rt::exact;

// The watertight decision is exact for the rounded, sheared vertices: recompute those exactly as
// the paper prescribes (dominant axis, shear by the rounded ratios dir[k] / dir[kz]) and decide
// the 2D point-in-triangle test of the origin with exact rational edge functions. The method must
// agree on every ray, without any tolerance. Rays aimed at shared edges of the icosphere produce
// edge functions whose two products round to the same Real although they differ: without the
// higher-precision recomputation of such zeros, the method would accept those triangles.
TEST(Watertight, DecisionIsExactForTheShearedVertices) {
    Rng rng(0x5eed000c);
    const Mesh mesh = icosphere(2);
    int rays = 0, rounded_zero = 0;
    for (const auto& e : mesh.edges()) {
        for (int j = 0; j < 6; ++j) {
            const Vec3& p = mesh.vertices[e[0]];
            const Vec3& q = mesh.vertices[e[1]];
            const Vec3 target = p + Real(rng.uniform(0, 1)) * (q - p);
            const Vec3 o = j < 3 ? target * Real(3) + rng.vec(-0.05, 0.05) : Vec3(0);
            const Ray ray{o, target - o};
            const Vec3& d = ray.direction;
            int kz = 0;
            for (int k = 1; k < 3; ++k)
                if (std::abs(d[k]) > std::abs(d[kz])) kz = k;
            int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
            if (d[kz] < 0) std::swap(kx, ky);
            const Real sx = d[kx] / d[kz], sy = d[ky] / d[kz];
            for (const auto& t : mesh.triangles) {
                Q x[3], y[3];
                Real fx[3], fy[3];
                for (int v = 0; v < 3; ++v) {
                    const Vec3 rel = mesh.vertices[t[v]] - o;
                    fx[v] = rel[kx] - sx * rel[kz];
                    fy[v] = rel[ky] - sy * rel[kz];
                    x[v] = Q(double(fx[v]));
                    y[v] = Q(double(fy[v]));
                }
                int signs[3];
                bool any_rounded_zero = false;
                for (int v = 0; v < 3; ++v) {  // edge opposite to vertex v: (v+1, v+2)
                    const int i = (v + 1) % 3, k = (v + 2) % 3;
                    signs[v] = CGAL::sign(x[k] * y[i] - y[k] * x[i]);
                    const Real rounded = fx[k] * fy[i] - fy[k] * fx[i];
                    if (rounded == 0 && signs[v] != 0) any_rounded_zero = true;
                }
                const bool has_neg = signs[0] < 0 || signs[1] < 0 || signs[2] < 0;
                const bool has_pos = signs[0] > 0 || signs[1] > 0 || signs[2] > 0;
                const bool exact_inside = has_neg != has_pos;  // not mixed, not all zero
                Hit hit;
                const bool got = intersect_triangle_watertight(
                    ray, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]],
                    Interval{-kInfinity, kInfinity}, hit);
                rounded_zero += any_rounded_zero;
                ++rays;
                EXPECT_EQ(got, exact_inside) << "triangle (" << t[0] << ", " << t[1] << ", " << t[2]
                                             << "), rounded zero " << any_rounded_zero;
                if (HasFailure()) return;
            }
        }
    }
    std::printf("[sheared exact] %d ray/triangle pairs, %d with an edge function rounded to 0\n",
                rays, rounded_zero);
    EXPECT_GT(rounded_zero, 0) << "the test no longer exercises the zero recomputation";
}

}  // namespace
}  // namespace rt
