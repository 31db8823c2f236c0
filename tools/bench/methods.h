// The intersection methods compared by the accuracy lab, templated on the scalar so one binary
// measures float and double side by side. These are the bench's own copies (the bench never links
// student code): Cramer's rule and the spheres as taught in stage 02, Moeller-Trumbore, and the
// watertight test written exactly as framework/geometry/watertight.cpp.
//
// Every function takes the open range (tmin, tmax) and returns a Result; none touches the scene.
#pragma once

#include <glm/glm.hpp>

#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>

namespace rt::bench {

template <typename T>
using V3 = glm::vec<3, T>;

template <typename T>
struct Result {
    bool hit = false;
    T t = 0;
    T beta = 0, gamma = 0;  // triangles: barycentric weights of b and c
};

template <typename T>
bool finite3(const V3<T>& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// ---------------------------------------------------------------------------------------------
// Triangles.

// Cramer's rule as taught: [a-b  a-c  d] (beta, gamma, t) = a - o.
template <typename T>
Result<T> cramer(const V3<T>& o, const V3<T>& d, const V3<T>& a, const V3<T>& b, const V3<T>& c,
                 T tmin, T tmax) {
    Result<T> r;
    const V3<T> col1 = a - b, col2 = a - c, rhs = a - o;
    const T det = glm::dot(col1, glm::cross(col2, d));
    if (det == 0 || !std::isfinite(det)) return r;
    const T t = glm::dot(col1, glm::cross(col2, rhs)) / det;
    if (!(tmin < t && t < tmax)) return r;
    const T gamma = glm::dot(col1, glm::cross(rhs, d)) / det;
    if (gamma < 0 || gamma > 1) return r;
    const T beta = glm::dot(rhs, glm::cross(col2, d)) / det;
    if (beta < 0 || beta > 1 - gamma) return r;
    return {true, t, beta, gamma};
}

// Moeller and Trumbore, "Fast, minimum storage ray/triangle intersection", JGT 1997 (no culling).
template <typename T>
Result<T> moller_trumbore(const V3<T>& o, const V3<T>& d, const V3<T>& a, const V3<T>& b,
                          const V3<T>& c, T tmin, T tmax) {
    Result<T> r;
    const V3<T> e1 = b - a, e2 = c - a;
    const V3<T> p = glm::cross(d, e2);
    const T det = glm::dot(e1, p);
    if (det == 0 || !std::isfinite(det)) return r;
    const T inv = T(1) / det;
    const V3<T> s = o - a;
    const T u = glm::dot(s, p) * inv;
    if (u < 0 || u > 1) return r;
    const V3<T> q = glm::cross(s, e1);
    const T v = glm::dot(d, q) * inv;
    if (v < 0 || u + v > 1) return r;
    const T t = glm::dot(e2, q) * inv;
    if (!(tmin < t && t < tmax)) return r;
    return {true, t, u, v};
}

// A seed course's method (the Leeds ray tracer): intersect the triangle's plane, then keep the
// point if it lies on the inner side of all three edges (cross(edge, p - start).n >= 0).
// Barycentrics from the sub-triangle areas, for the report's comparison.
template <typename T>
Result<T> plane_same_side(const V3<T>& o, const V3<T>& d, const V3<T>& a, const V3<T>& b,
                          const V3<T>& c, T tmin, T tmax) {
    Result<T> r;
    const V3<T> n = glm::cross(b - a, c - a);
    const T denom = glm::dot(n, d);
    if (denom == 0 || !std::isfinite(denom)) return r;
    const T t = glm::dot(n, a - o) / denom;
    if (!(tmin < t && t < tmax)) return r;
    const V3<T> p = o + t * d;
    if (glm::dot(glm::cross(b - a, p - a), n) < 0 || glm::dot(glm::cross(c - b, p - b), n) < 0 ||
        glm::dot(glm::cross(a - c, p - c), n) < 0)
        return r;
    const T area = glm::dot(n, n);
    return {true, t, glm::dot(glm::cross(p - a, c - a), n) / area,
            glm::dot(glm::cross(b - a, p - a), n) / area};
}

namespace detail {
// a*b - c*d with the exact sign; see framework/geometry/watertight.cpp.
template <typename T>
T difference_of_products_exact_sign(T a, T b, T c, T d) {
    if constexpr (std::is_same_v<T, float>) {
        return T(double(a) * double(b) - double(c) * double(d));
    } else {
        const T cd = c * d;
        const T cd_error = std::fma(-c, d, cd);
        const T ab_minus_cd = std::fma(a, b, -cd);
        return ab_minus_cd + cd_error;
    }
}
}  // namespace detail

// Woop, Benthin and Wald, "Watertight Ray/Triangle Intersection", JCGT 2(1), 2013: the same
// steps as framework/geometry/watertight.cpp, on T. Fused = true evaluates the edge functions
// x*y - z*w as fma(x, y, -(z*w)), what -ffp-contract=fast may do to the plain code: the lab's
// "watertight FMA" row shows what that costs.
template <typename T, bool Fused = false>
Result<T> watertight(const V3<T>& o, const V3<T>& d, const V3<T>& a, const V3<T>& b, const V3<T>& c,
                     T tmin, T tmax) {
    Result<T> r;
    if (!finite3(d)) return r;
    const V3<T> ad = glm::abs(d);
    int kz = 0;
    if (ad.y > ad[kz]) kz = 1;
    if (ad.z > ad[kz]) kz = 2;
    if (d[kz] == 0) return r;
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    if (d[kz] < 0) std::swap(kx, ky);
    const T Sx = d[kx] / d[kz], Sy = d[ky] / d[kz], Sz = T(1) / d[kz];
    const V3<T> A = a - o, B = b - o, C = c - o;
    const T Ax = A[kx] - Sx * A[kz], Ay = A[ky] - Sy * A[kz];
    const T Bx = B[kx] - Sx * B[kz], By = B[ky] - Sy * B[kz];
    const T Cx = C[kx] - Sx * C[kz], Cy = C[ky] - Sy * C[kz];
    T U, V, W;
    if constexpr (Fused) {
        U = std::fma(Cx, By, -(Cy * Bx));
        V = std::fma(Ax, Cy, -(Ay * Cx));
        W = std::fma(Bx, Ay, -(By * Ax));
    } else {
        U = Cx * By - Cy * Bx;
        V = Ax * Cy - Ay * Cx;
        W = Bx * Ay - By * Ax;
    }
    if (U == 0 || V == 0 || W == 0) {
        U = detail::difference_of_products_exact_sign(Cx, By, Cy, Bx);
        V = detail::difference_of_products_exact_sign(Ax, Cy, Ay, Cx);
        W = detail::difference_of_products_exact_sign(Bx, Ay, By, Ax);
    }
    if ((U < 0 || V < 0 || W < 0) && (U > 0 || V > 0 || W > 0)) return r;
    const T det = U + V + W;
    if (det == 0 || !std::isfinite(det)) return r;
    const T Az = Sz * A[kz], Bz = Sz * B[kz], Cz = Sz * C[kz];
    T Tn = U * Az + V * Bz + W * Cz;
    T det_abs = det;
    if (det < 0) {
        det_abs = -det;
        Tn = -Tn;
    }
    if (!(Tn > tmin * det_abs) || !(Tn < tmax * det_abs)) return r;
    const T t = Tn * (T(1) / det_abs);
    if (!(tmin < t && t < tmax)) return r;
    return {true, t, V / det, W / det};
}

// ---------------------------------------------------------------------------------------------
// Spheres: |o + t d - c|^2 = r^2. Each returns the smallest root inside (tmin, tmax).

template <typename T>
Result<T> pick_root(T t0, T t1, T tmin, T tmax) {
    if (t0 > t1) std::swap(t0, t1);
    if (tmin < t0 && t0 < tmax) return {true, t0};
    if (tmin < t1 && t1 < tmax) return {true, t1};
    return {};
}

// The roots of a t^2 + 2 hb t + c = 0, given its discriminant disc = hb^2 - a c however computed,
// in the q-form: q = -(hb + sign(hb) sqrt(disc)), roots q / a and c / q, so that neither root is
// a difference of nearly equal numbers. The smallest inside (tmin, tmax).
template <typename T>
Result<T> qform_root(T a, T hb, T c, T disc, T tmin, T tmax) {
    if (disc < 0) return {};
    const T q = -(hb + std::copysign(std::sqrt(disc), hb));
    const T t0 = q / a;
    return pick_root(t0, q != 0 ? c / q : t0, tmin, tmax);
}

// The textbook quadratic: b = 2 d.(o-c), disc = b^2 - 4ac, t = (-b -+ sqrt(disc)) / 2a.
template <typename T>
Result<T> sphere_textbook(const V3<T>& o, const V3<T>& d, const V3<T>& center, T radius, T tmin,
                          T tmax) {
    const V3<T> oc = o - center;
    const T a = glm::dot(d, d);
    if (!(a > 0) || !std::isfinite(a)) return {};
    const T b = 2 * glm::dot(oc, d);
    const T c = glm::dot(oc, oc) - radius * radius;
    const T disc = b * b - 4 * a * c;
    if (disc < 0) return {};
    const T s = std::sqrt(disc);
    return pick_root((-b - s) / (2 * a), (-b + s) / (2 * a), tmin, tmax);
}

// A seed course's geometric method (the Arizona lecture): with a unit direction, t_ca = L.d for
// L = c - o, and a miss when t_ca < 0 (the centre is behind the origin); else d2 = L.L - t_ca^2,
// a miss when d2 > r^2, and t = t_ca -+ sqrt(r^2 - d2). The early exit is wrong from inside a
// sphere whose centre is behind the origin: the report counts those as false misses.
template <typename T>
Result<T> sphere_geometric(const V3<T>& o, const V3<T>& d, const V3<T>& center, T radius, T tmin,
                           T tmax) {
    const T length = glm::length(d);
    if (!(length > 0) || !std::isfinite(length)) return {};
    const V3<T> unit = d / length;
    const V3<T> l = center - o;
    const T t_ca = glm::dot(l, unit);
    if (t_ca < 0) return {};
    const T d2 = glm::dot(l, l) - t_ca * t_ca;
    if (d2 > radius * radius) return {};
    const T t_hc = std::sqrt(radius * radius - d2);
    return pick_root((t_ca - t_hc) / length, (t_ca + t_hc) / length, tmin, tmax);
}

// The coefficients of the q-form methods: a = d.d, half b (hb = d.(o-c)), c = |o-c|^2 - r^2;
// nullopt when a is zero or not finite.
template <typename T>
struct HalfBQuadratic {
    V3<T> oc;
    T a, hb, c;
};
template <typename T>
std::optional<HalfBQuadratic<T>> half_b_quadratic(const V3<T>& o, const V3<T>& d,
                                                  const V3<T>& center, T radius) {
    const V3<T> oc = o - center;
    const T a = glm::dot(d, d);
    if (!(a > 0) || !std::isfinite(a)) return std::nullopt;
    const T hb = glm::dot(oc, d);
    const T c = glm::dot(oc, oc) - radius * radius;
    return HalfBQuadratic<T>{oc, a, hb, c};
}

// The stable q-form: disc = hb^2 - a c, roots by qform_root.
template <typename T>
Result<T> sphere_qform(const V3<T>& o, const V3<T>& d, const V3<T>& center, T radius, T tmin,
                       T tmax) {
    const auto q = half_b_quadratic(o, d, center, radius);
    if (!q) return {};
    return qform_root(q->a, q->hb, q->c, q->hb * q->hb - q->a * q->c, tmin, tmax);
}

// Ray Tracing Gems, ch. 7 (Haines, Guenther, Akenine-Moeller): the discriminant as
// a (r^2 - |l|^2) with l = oc - (b/a) d, the vector from the centre to the closest point of the
// line. No cancellation for small spheres far away. Roots by the q-form. This is the stage 02
// solution's form.
template <typename T>
Result<T> sphere_rtg(const V3<T>& o, const V3<T>& d, const V3<T>& center, T radius, T tmin,
                     T tmax) {
    const auto q = half_b_quadratic(o, d, center, radius);
    if (!q) return {};
    const V3<T> l = q->oc - (q->hb / q->a) * d;
    return qform_root(q->a, q->hb, q->c, q->a * (radius * radius - glm::dot(l, l)), tmin, tmax);
}

// ---------------------------------------------------------------------------------------------
// Where secondary rays start. pbrt-v4's OffsetRayOrigin (Pharr, Jakob, Humphreys, PBR 4th ed.,
// 6.8.6), on T. The framework's own version (framework/geometry/offset.h) is on rt::Real only;
// this copy exists so the bench can run it in float and double. Keep the two in step.

template <typename T>
T gamma_bound(int n) {
    constexpr T u = std::numeric_limits<T>::epsilon() / 2;
    return T(n) * u / (1 - T(n) * u);
}

// The hit point rebuilt from barycentrics and its per-coordinate error bound (pbrt 6.8.5).
template <typename T>
void triangle_surface_point(const V3<T>& a, const V3<T>& b, const V3<T>& c, T beta, T gamma,
                            V3<T>& point, V3<T>& error) {
    const T alpha = 1 - beta - gamma;
    point = alpha * a + beta * b + gamma * c;
    error = gamma_bound<T>(7) * (glm::abs(alpha * a) + glm::abs(beta * b) + glm::abs(gamma * c));
}

template <typename T>
V3<T> offset_ray_origin(const V3<T>& point, const V3<T>& error, const V3<T>& normal,
                        const V3<T>& direction) {
    const T dist = glm::dot(glm::abs(normal), error);
    V3<T> offset = dist * normal;
    if (glm::dot(direction, normal) < 0) offset = -offset;
    V3<T> origin = point + offset;
    for (int k = 0; k < 3; ++k) {
        if (offset[k] > 0)
            origin[k] = std::nextafter(origin[k], std::numeric_limits<T>::infinity());
        else if (offset[k] < 0)
            origin[k] = std::nextafter(origin[k], -std::numeric_limits<T>::infinity());
    }
    return origin;
}

}  // namespace rt::bench
