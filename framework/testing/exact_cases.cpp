// Stage 02's hard intersection cases and their exact answers (exact_cases.h), compiled once into
// rt_exact_cases. The generators are the loops stage 02's CGAL test ran inline, draw for draw.
#include "testing/exact_cases.h"

#include <algorithm>
#include <cmath>

namespace rt::exact {

namespace {

double max_abs_of(const Vec3& v) {
    return std::max({std::abs(double(v.x)), std::abs(double(v.y)), std::abs(double(v.z))});
}
double length_of(const Vec3& v) {
    return std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z);
}

TriangleCase triangle_case(const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c) {
    return {ray, a, b, c, exact_triangle(ray, a, b, c)};
}

// A random ray aimed at a random point near (and often inside) the triangle.
Ray ray_towards(Rng& rng, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& origin) {
    const Real u = Real(rng.uniform(-0.2, 1.2)), v = Real(rng.uniform(-0.2, 1.2));
    Real bu = u, bv = v;
    if (u + v > Real(1.3)) bu = Real(1.3) - v;  // keep most targets near the triangle
    const Vec3 target = a + bu * (b - a) + bv * (c - a);
    const Real scale = Real(std::ldexp(1.0, rng.integer(-3, 3)) * rng.uniform(0.75, 1.5));
    return Ray{origin, (target - origin) * scale};  // non-unit directions on purpose
}

}  // namespace

TriangleScales triangle_scales(const TriangleCase& c) {
    TriangleScales s;
    const Vec3 n = glm::cross(c.b - c.a, c.c - c.a);
    s.dlen = length_of(c.ray.direction);
    s.cos = std::abs(glm::dot(n, c.ray.direction)) / (length_of(n) * s.dlen);
    s.t_exact = c.truth.parallel ? 0 : CGAL::to_double(c.truth.t);
    s.L = std::max({max_abs_of(c.ray.origin), max_abs_of(c.a), max_abs_of(c.b), max_abs_of(c.c)}) +
          std::abs(s.t_exact) * s.dlen;
    const double emax =
        std::max({length_of(c.b - c.a), length_of(c.c - c.b), length_of(c.a - c.c)});
    s.aspect = emax * emax / length_of(n);
    return s;
}

double vertex_size(const TriangleCase& c) {
    return std::max({max_abs_of(c.a), max_abs_of(c.b), max_abs_of(c.c)});
}

std::vector<TriangleCase> random_triangle_cases(int count) {
    std::vector<TriangleCase> cases;
    Rng rng(0x5eed0001);
    for (int i = 0; i < count; ++i) {
        const Vec3 a = rng.vec(-1, 1), b = rng.vec(-1, 1), c = rng.vec(-1, 1);
        if (glm::length(glm::cross(b - a, c - a)) < Real(0.05)) continue;  // slivers: own family
        const Vec3 origin = rng.vec(-4, 4);
        cases.push_back(triangle_case(ray_towards(rng, a, b, c, origin), a, b, c));
    }
    return cases;
}

std::vector<TriangleCase> grazing_triangle_cases(int count) {
    std::vector<TriangleCase> cases;
    Rng rng(0x5eed0002);
    for (int i = 0; i < count; ++i) {
        const Vec3 a = rng.vec(-1, 1), b = rng.vec(-1, 1), c = rng.vec(-1, 1);
        const Vec3 n = glm::cross(b - a, c - a);
        if (glm::length(n) < Real(0.2)) continue;
        const Vec3 unit_n = glm::normalize(n);
        Vec3 along = glm::normalize(glm::cross(unit_n, rng.unit()));
        const double angle = std::pow(10.0, rng.uniform(-5, -1));
        const Real u = Real(rng.uniform(-0.1, 1.1)), v = Real(rng.uniform(-0.1, 1.1) * (1 - u));
        const Vec3 target = a + u * (b - a) + v * (c - a);
        const Vec3 dir = along * Real(std::cos(angle)) - unit_n * Real(std::sin(angle));
        const Real dist = Real(rng.uniform(0.5, 3));
        cases.push_back(triangle_case(Ray{target - dist * dir, dir}, a, b, c));
    }
    return cases;
}

std::vector<TriangleCase> sliver_triangle_cases(int count) {
    std::vector<TriangleCase> cases;
    Rng rng(0x5eed0003);
    for (int i = 0; i < count; ++i) {
        const Vec3 a = rng.vec(-1, 1), b = rng.vec(-1, 1);
        const Vec3 side = glm::normalize(glm::cross(b - a, rng.unit()));
        const Real thin = Real(std::pow(10.0, rng.uniform(-5, -3)));
        Vec3 c;
        if (i % 2 == 0)
            c = b + thin * side * glm::length(b - a);  // needle: |bc| tiny
        else
            c = (a + b) * Real(0.5) + thin * side * glm::length(b - a);  // cap
        if (glm::length(glm::cross(b - a, c - a)) == 0) continue;
        // Aim at the sliver itself: a point on the segment ab or just beside it.
        const Real s = Real(rng.uniform(-0.05, 1.05));
        const Vec3 target =
            a + s * (b - a) +
            Real(rng.uniform(-1, 2)) * (c - (a + b) * Real(0.5)) * Real(i % 2 == 0 ? 0 : 1);
        const Vec3 origin = rng.vec(-4, 4);
        cases.push_back(triangle_case(Ray{origin, target - origin}, a, b, c));
    }
    return cases;
}

std::vector<TriangleCase> scaled_triangle_cases(int count) {
    std::vector<TriangleCase> cases;
    Rng rng(0x5eed0004);
    for (int i = 0; i < count; ++i) {
        const int kind = i % 3;
        const Real scale = kind == 1 ? Real(1e6) : kind == 2 ? Real(1e-4) : Real(1);
        const Vec3 offset = kind == 0 ? rng.vec(-1e4, 1e4) : Vec3(0);
        const Vec3 a = rng.vec(-1, 1) * scale + offset, b = rng.vec(-1, 1) * scale + offset,
                   c = rng.vec(-1, 1) * scale + offset;
        const Vec3 n = glm::cross(b - a, c - a);
        if (!(glm::length(n) >= Real(0.05) * scale * scale)) continue;
        const Vec3 origin = rng.vec(-4, 4) * scale + offset;
        cases.push_back(triangle_case(ray_towards(rng, a, b, c, origin), a, b, c));
    }
    return cases;
}

std::vector<TriangleCase> parallel_triangle_cases() {
    const Vec3 a(0, 0, 0), b(1, 1, 0), c(0, 1, 1);  // normal (1, -1, 1): small exact integers
    const Vec3 dirs[] = {{1, 1, 0}, {0, 1, 1}, {1, 0, -1}, {2, 1, -1}, {0.5, 0.25, -0.25}};
    const Vec3 origins[] = {Vec3(0.25, 0.5, 0.25) - Vec3(1, 1, 0) * Real(2),    // in the plane
                            Vec3(0, 0.5, 0.25) + Vec3(1, -1, 1) * Real(0.125),  // beside it
                            Vec3(-3, -2, 1)};
    std::vector<TriangleCase> cases;
    for (const Vec3& d : dirs)
        for (const Vec3& o : origins) cases.push_back(triangle_case(Ray{o, d}, a, b, c));
    return cases;
}

std::vector<TriangleCase> exact_origin_on_triangle_cases() {
    const Vec3 a(-1, -1, 0.5), b(1, -1, 0.5), c(0, 1, 0.5);
    std::vector<TriangleCase> cases;
    for (const Vec3 o : {Vec3(0, 0, 0.5), Vec3(0.25, -0.5, 0.5), Vec3(-1, -1, 0.5)})
        for (const Vec3 d : {Vec3(0, 0, 1), Vec3(0.5, 0.25, -1), Vec3(-1, 2, 3)})
            cases.push_back(triangle_case(Ray{o, d}, a, b, c));
    return cases;
}

std::vector<TriangleCase> origin_on_triangle_cases(int count) {
    std::vector<TriangleCase> cases;
    Rng rng(0x5eed0005);
    for (int i = 0; i < count && cases.size() < 200; ++i) {
        const Vec3 a = rng.vec(-1, 1), b = rng.vec(-1, 1), c = rng.vec(-1, 1);
        if (glm::length(glm::cross(b - a, c - a)) < Real(0.1)) continue;
        // A vertex, or an edge midpoint when it happens to be exact, lies exactly on the plane.
        const Vec3 o = i % 2 ? a : (a + b) * Real(0.5);
        const TriangleCase one = triangle_case(Ray{o, rng.unit()}, a, b, c);
        if (!one.truth.origin_in_plane || one.truth.parallel) continue;
        cases.push_back(one);
    }
    return cases;
}

SphereScales sphere_scales(const SphereCase& c) {
    SphereScales s;
    s.oc = length_of(c.ray.origin - c.sphere.center);
    s.r = c.sphere.radius;
    s.h = std::sqrt(std::max(0.0, -c.truth.tangency * 2 * s.r));
    return s;
}

std::vector<SphereCase> random_sphere_cases(int count) {
    std::vector<SphereCase> cases;
    Rng rng(0x5eed0007);
    for (int i = 0; i < count; ++i) {
        const Sphere s{rng.vec(-5, 5), Real(std::pow(10.0, rng.uniform(-1, 1)))};
        const Vec3 o = rng.vec(-15, 15);
        Vec3 target = s.center + rng.vec(-1.2, 1.2) * s.radius;
        if (i % 4 == 0) {  // at the rim: within 1e-7 .. 1e-3 r of tangency, on either side
            const Vec3 w = glm::normalize(s.center - o);
            const Vec3 side = glm::normalize(glm::cross(w, rng.unit()));
            const double off = std::pow(10.0, rng.uniform(-7, -3)) * (i % 8 == 0 ? 1 : -1);
            target = s.center + side * Real(double(s.radius) * (1 + off));
        }
        const Ray ray{o, (target - o) * Real(rng.uniform(0.1, 10))};
        SphereCase one{ray, s, exact_sphere(ray, s)};
        const double oc = length_of(o - s.center);
        one.well_conditioned =
            one.truth.tangency < -0.1 * s.radius && std::abs(oc - s.radius) > 0.5 * s.radius;
        cases.push_back(one);
    }
    return cases;
}

std::vector<SphereCase> small_far_sphere_cases(int count) {
    std::vector<SphereCase> cases;
    Rng rng(0x5eed0008);
    for (int i = 0; i < count; ++i) {
        const Vec3 center = rng.unit() * Real(1e4);
        const Sphere s{center, 1};
        const Vec3 o = rng.vec(-1, 1);
        const Vec3 target = center + rng.vec(-0.6, 0.6);
        const Ray ray{o, glm::normalize(target - o) * Real(rng.uniform(0.5, 2))};
        const SphereTruth truth = exact_sphere(ray, s);
        if (!(truth.tangency < -0.1)) continue;
        cases.push_back({ray, s, truth, true});
    }
    return cases;
}

std::vector<SphereCase> large_sphere_above_cases(int count) {
    std::vector<SphereCase> cases;
    Rng rng(0x5eed0009);
    for (int i = 0; i < count; ++i) {
        const Sphere s{rng.vec(-10, 10), Real(1e3)};
        const Vec3 up = rng.unit();
        const double height = std::pow(10.0, rng.uniform(-2, 0));
        const Vec3 o = s.center + up * Real(s.radius + height);
        Vec3 dir = glm::normalize(-up * Real(rng.uniform(0.05, 1)) + rng.unit() * Real(0.5));
        if (glm::dot(dir, up) >= 0) continue;
        const Ray ray{o, dir};
        cases.push_back({ray, s, exact_sphere(ray, s)});
    }
    return cases;
}

std::vector<SphereCase> large_sphere_inside_cases(int count) {
    std::vector<SphereCase> cases;
    Rng rng(0x5eed000d);
    for (int i = 0; i < count; ++i) {
        const Vec3 center(Real(rng.integer(-50, 50)), Real(rng.integer(-50, 50)),
                          Real(rng.integer(-50, 50)));
        const Sphere s{center, 1000};
        Vec3 up(0);
        up[rng.integer(0, 2)] = Real(i % 2 ? 1 : -1);
        const Vec3 o = center + up * Real(1000 - rng.integer(1, 8));
        const Ray ray{o, up * Real(rng.uniform(0.5, 2)) + rng.vec(-0.05, 0.05)};
        cases.push_back({ray, s, exact_sphere(ray, s)});
    }
    return cases;
}

std::vector<SphereCase> origin_on_sphere_cases() {
    const Sphere s{Vec3(1, 2, 3), 5};
    const Vec3 o = s.center + Vec3(3, 4, 0);
    std::vector<SphereCase> cases;
    for (const Vec3 d :
         {Vec3(-3, -4, 0) + Vec3(0, 1, 2), Vec3(3, 4, 0) + Vec3(0, 1, 2), Vec3(-4, 3, 0)}) {
        const Ray ray{o, d};
        cases.push_back({ray, s, exact_sphere(ray, s)});
    }
    return cases;
}

std::vector<BoxCase> box_cases(int count) {
    std::vector<BoxCase> cases;
    Rng rng(0x5eed000a);
    for (int i = 0; i < count; ++i) {
        const Vec3 p = rng.vec(-3, 3), q = rng.vec(-3, 3);
        const Box box{glm::min(p, q), glm::max(p, q)};
        const Vec3 o = rng.vec(-6, 6);
        Vec3 target = rng.vec(-3.5, 3.5);
        if (i % 4 == 0) target = box.min;  // a corner (to within the rounding of d)
        if (i % 4 == 1) target[rng.integer(0, 2)] = box.max[rng.integer(0, 2)];
        Vec3 d = target - o;
        if (i % 7 == 0) d[rng.integer(0, 2)] = 0;  // parallel to a slab
        const Ray ray{o, d * Real(rng.uniform(0.2, 5))};
        cases.push_back({ray, box, exact_box(ray, box)});
    }
    return cases;
}

double plane_unit(const PlaneCase& c, double eps) {
    const double dlen = length_of(c.ray.direction);
    const double cos =
        std::abs(glm::dot(c.plane.normal, c.ray.direction)) / (length_of(c.plane.normal) * dlen);
    const double t_exact = CGAL::to_double(c.truth.t);
    return eps * (length_of(c.plane.point - c.ray.origin) + std::abs(t_exact) * dlen) / cos;
}

std::vector<PlaneCase> plane_cases(int count) {
    std::vector<PlaneCase> cases;
    Rng rng(0x5eed000b);
    for (int i = 0; i < count; ++i) {
        const Plane plane{rng.vec(-10, 10), rng.unit()};
        const Ray ray{rng.vec(-10, 10), rng.unit() * Real(rng.uniform(0.1, 10))};
        cases.push_back({ray, plane, exact_plane(ray, plane)});
    }
    return cases;
}

std::vector<PlaneCase> parallel_plane_cases() {
    std::vector<PlaneCase> cases;
    // n = normalize(1, 1, 0) in Real, so n.x == n.y: d = (1, -1, z) is exactly parallel.
    const Plane plane{Vec3(2, -1, 0.5), glm::normalize(Vec3(1, 1, 0))};
    for (const Vec3 o : {Vec3(5, 6, 7), Vec3(2, -1, 0.5), Vec3(3, -2, 0.5)}) {  // 2, 3: in it
        const Ray ray{o, Vec3(1, -1, 3)};
        cases.push_back({ray, plane, exact_plane(ray, plane)});
    }
    // Origin exactly on the plane, direction across it: exact t == 0, outside (0, inf).
    const Plane flat{Vec3(0, 1.5, 0), Vec3(0, 1, 0)};
    for (const Vec3 d : {Vec3(0, 1, 0), Vec3(0.3f, -1, 0.2f)}) {
        const Ray ray{Vec3(5, 1.5, -3), d};
        cases.push_back({ray, flat, exact_plane(ray, flat)});
    }
    return cases;
}

}  // namespace rt::exact
