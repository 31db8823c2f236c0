// Watertight ray/triangle intersection after Woop, Benthin and Wald, "Watertight Ray/Triangle
// Intersection", Journal of Computer Graphics Techniques 2(1), 2013.
//
// Idea: transform the problem into a frame where the ray is the +z axis through the origin. The
// test then becomes a 2D point-in-triangle test of the origin against the projected triangle,
// decided by three 2D edge functions. Each edge function depends only on the two (transformed)
// vertices of its edge and is computed by the same formula, whichever triangle asks, so two
// triangles sharing an edge evaluate bit-identical (or exactly negated) values for it: a ray can
// never fall in a gap between them. The signs of the edge functions are made exact (see the
// fallback below), so the decision is exact for the rounded transformed vertices.
//
// This file must be compiled without floating-point contraction (-ffp-contract=off, set for the
// whole project): an FMA in one expression but not in another evaluation of the "same" value
// would break the bit-identical property that watertightness rests on.
#include "geometry/watertight.h"

#include <cmath>
#include <type_traits>
#include <utility>

namespace rt {
namespace {

// a * b - c * d with the sign exactly right (and zero exactly when the true value is zero).
// Called only when the plain evaluation gave exactly 0, which may be a rounding artefact: the two
// products can round to the same value although they differ.
Real difference_of_products_exact_sign(Real a, Real b, Real c, Real d) {
    if constexpr (std::is_same_v<Real, float>) {
        // The paper's fallback: a product of two floats (24-bit significands) fits exactly in a
        // double (53 bits), so both products are exact and the one rounding of the subtraction
        // keeps the sign (rounding is monotonic and never turns a nonzero value into zero).
        const double value = double(a) * double(b) - double(c) * double(d);
        return Real(value);  // a tiny nonzero double may underflow to 0 in float: accepted
    } else {
        // Real is double: no wider hardware type holds the products exactly. Kahan's algorithm
        // with fused multiply-adds recovers each product's rounding error exactly and returns
        // a * b - c * d with a relative error of at most 2 units in the last place, which in
        // particular gets the sign (and exact zero) right. The fma calls are explicit library
        // calls, unaffected by -ffp-contract=off.
        const Real cd = c * d;
        const Real cd_error = std::fma(-c, d, cd);  // cd - c*d exactly
        const Real ab_minus_cd = std::fma(a, b, -cd);
        return ab_minus_cd + cd_error;
    }
}

}  // namespace

namespace {

// Steps 1 and 2: the axes relabelled so that the direction's dominant axis is z, and the shear
// that maps the direction to (0, 0, 1).
struct Shear {
    int kx = 0, ky = 0, kz = 0;
    Real Sx = 0, Sy = 0, Sz = 0;
};

// False for a zero direction.
bool make_shear(const Vec3& dir, Shear& shear) {
    // 1. The dominant axis kz of the direction becomes the new z axis: dividing by dir[kz] below
    //    is then as well conditioned as it can be (|dir[kz]| >= |dir[i]|, so the shear factors are
    //    in [-1, 1]).
    const Vec3 abs_dir = glm::abs(dir);
    int kz = 0;
    if (abs_dir.y > abs_dir[kz]) kz = 1;
    if (abs_dir.z > abs_dir[kz]) kz = 2;
    if (dir[kz] == 0) return false;  // all components zero
    int kx = (kz + 1) % 3;
    int ky = (kx + 1) % 3;
    // Relabelling the axes is a rotation (kx, ky, kz cyclic) as long as dir[kz] > 0. If the ray
    // points down the new z axis, the frame would be mirrored, which flips the sign of every edge
    // function; swapping kx and ky mirrors it back, so the winding (and front_face) keeps its
    // meaning. Since both windings are accepted here this is not needed for the hit decision,
    // but it keeps the sign of det equal to the sign of the geometric orientation.
    if (dir[kz] < 0) std::swap(kx, ky);

    // 2. Shear constants: the transform (x, y, z) -> (x - Sx z, y - Sy z, Sz z) maps the
    //    direction to (0, 0, 1). Only the first two are needed for the 2D test; Sz is applied to
    //    z afterwards, and only if the 2D test passes.
    shear = {kx, ky, kz, dir[kx] / dir[kz], dir[ky] / dir[kz], Real(1) / dir[kz]};
    return true;
}

// Steps 3 to 5: the edge functions U, V, W of the sheared triangle (A, B, C relative to the ray
// origin), their zeros recomputed with an exact sign.
struct EdgeFunctions {
    Real U, V, W;
};

EdgeFunctions edge_functions(const Shear& s, const Vec3& A, const Vec3& B, const Vec3& C) {
    // 3. Vertices relative to the ray origin, then sheared. Each transformed vertex depends only
    //    on the vertex and the ray, so every triangle sharing it sees the same bits.
    const Real Ax = A[s.kx] - s.Sx * A[s.kz];
    const Real Ay = A[s.ky] - s.Sy * A[s.kz];
    const Real Bx = B[s.kx] - s.Sx * B[s.kz];
    const Real By = B[s.ky] - s.Sy * B[s.kz];
    const Real Cx = C[s.kx] - s.Sx * C[s.kz];
    const Real Cy = C[s.ky] - s.Sy * C[s.kz];

    // 4. Edge functions: twice the signed areas of the 2D triangles (origin, B, C), (origin, C, A)
    //    and (origin, A, B). U belongs to edge BC (it is the unnormalised barycentric weight of
    //    vertex a), V to edge CA (weight of b), W to edge AB (weight of c). A neighbour that
    //    shares edge BC evaluates Bx * Cy - By * Cx or Cx * By - Cy * Bx: the same products,
    //    hence exactly the same value or its exact negation.
    Real U = Cx * By - Cy * Bx;
    Real V = Ax * Cy - Ay * Cx;
    Real W = Bx * Ay - By * Ax;

    // 5. A rounded result of exactly 0 is ambiguous: the two products may differ in their true
    //    values yet round to the same number. A nonzero rounded result already has the right sign
    //    (rounding is monotonic), so only the zeros are recomputed, in higher precision. Without
    //    this, a ray through a shared edge could see U == 0 for one triangle where its neighbour
    //    sees a nonzero value of the wrong sign, and slip between them.
    if (U == 0 || V == 0 || W == 0) {
        U = difference_of_products_exact_sign(Cx, By, Cy, Bx);
        V = difference_of_products_exact_sign(Ax, Cy, Ay, Cx);
        W = difference_of_products_exact_sign(Bx, Ay, By, Ax);
    }
    return {U, V, W};
}

}  // namespace

bool intersect_triangle_watertight(const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c,
                                   Interval t_range, Hit& hit) {
    const Vec3& dir = ray.direction;
    // A zero, NaN or infinite direction hits nothing. Checked first so that nothing below divides
    // by zero or propagates NaN into a "hit".
    if (!all_finite(dir)) return false;
    Shear shear;
    if (!make_shear(dir, shear)) return false;
    // Steps 3 to 5 (edge_functions) on the vertices relative to the ray origin.
    const Vec3 A = a - ray.origin;
    const Vec3 B = b - ray.origin;
    const Vec3 C = c - ray.origin;
    const auto [U, V, W] = edge_functions(shear, A, B, C);

    // 6. Inside test for both windings (no backface culling): the origin is inside when the
    //    three edge functions do not have mixed signs. Zeros are compatible with either sign, so
    //    points on edges and vertices count as inside, for both triangles sharing the edge.
    if ((U < 0 || V < 0 || W < 0) && (U > 0 || V > 0 || W > 0)) return false;

    // 7. The determinant (twice the projected area). Zero: the ray is parallel to the plane of the
    //    triangle (it projects to a segment) or the triangle is degenerate; report a miss.
    const Real det = U + V + W;
    if (det == 0 || !std::isfinite(det)) return false;

    // 8. Scaled hit distance: T / det is t. Interpolating the sheared z coordinates with the
    //    unnormalised weights avoids a division before we know the hit is in range.
    const Real Az = shear.Sz * A[shear.kz];
    const Real Bz = shear.Sz * B[shear.kz];
    const Real Cz = shear.Sz * C[shear.kz];
    Real T = U * Az + V * Bz + W * Cz;

    // 9. Range test in the scaled form: t_min < T / det < t_max, multiplied out by det. Making det
    //    positive first (flipping T with it) keeps the inequalities pointing the same way for both
    //    windings. The products with infinite bounds are +-inf, which compare as intended.
    Real det_abs = det;
    if (det < 0) {
        det_abs = -det;
        T = -T;
    }
    if (!(T > t_range.min * det_abs) || !(T < t_range.max * det_abs)) return false;

    // 10. Only now divide. The scaled test and the rounded quotient can disagree in the last bit
    //     when t sits right at a bound, so check the contract (open interval) on the value that is
    //     actually reported as well.
    const Real inv_det = Real(1) / det_abs;
    const Real t = T * inv_det;
    if (!t_range.contains(t)) return false;
    // V and W were not flipped with T; dividing by the signed det gives the weights, which are
    // >= 0 whatever the winding.
    const Real beta = V / det;
    const Real gamma = W / det;

    hit.t = t;
    hit.point = ray.at(t);
    hit.set_face_normal(ray, glm::normalize(glm::cross(b - a, c - a)));
    hit.uv = Vec2(beta, gamma);
    return true;
}

}  // namespace rt
