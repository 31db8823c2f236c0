// The accuracy lab's cases (see scenarios.h): random, sliver and grazing triangles, closed meshes
// with rays through or beside their edges and vertices, and sphere scenarios, all from a seed.
#include "bench/scenarios.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

#include "geometry/procedural_mesh.h"

namespace rt::bench::detail {

using exact::Rng;

namespace {

V3f to_f(const V3d& v) {
    return V3f(float(v.x), float(v.y), float(v.z));
}
V3d to_d(const V3f& v) {
    return V3d(v);
}
bool exact_in_float(const V3d& v) {
    return to_d(to_f(v)) == v;
}
V3d snap(const V3d& v, double grid) {
    return glm::round(v / grid) * grid;
}

}  // namespace

V3d rvec(Rng& rng, double lo, double hi) {
    const double x = rng.uniform(lo, hi), y = rng.uniform(lo, hi), z = rng.uniform(lo, hi);
    return {x, y, z};
}
V3d runit(Rng& rng) {
    for (;;) {
        const V3d v = rvec(rng, -1, 1);
        const double l = glm::length(v);
        if (l > 0.1 && l <= 1) return v / l;
    }
}
double log_uniform(Rng& rng, double lo_exp, double hi_exp) {
    return std::pow(10.0, rng.uniform(lo_exp, hi_exp));
}

// A random ray aimed at a point near (often inside) the triangle.
TriangleCase towards(Rng& rng, const V3d& a, const V3d& b, const V3d& c, const V3d& origin) {
    double u = rng.uniform(-0.2, 1.2), v = rng.uniform(-0.2, 1.2);
    if (u + v > 1.3) u = 1.3 - v;
    const V3d target = a + u * (b - a) + v * (c - a);
    const double scale = std::ldexp(1.0, rng.integer(-3, 3)) * rng.uniform(0.75, 1.5);
    return {to_f(origin), to_f((target - origin) * scale), to_f(a), to_f(b), to_f(c)};
}

namespace {

void make_random(Scenario& s, Rng& rng, int n) {
    while (int(s.tris.size()) < n) {
        const V3d a = rvec(rng, -1, 1), b = rvec(rng, -1, 1), c = rvec(rng, -1, 1);
        if (glm::length(glm::cross(b - a, c - a)) < 0.05) continue;
        s.tris.push_back(towards(rng, a, b, c, rvec(rng, -4, 4)));
    }
}

void make_sliver(Scenario& s, Rng& rng, int n) {
    for (int i = 0; int(s.tris.size()) < n; ++i) {
        const V3d a = rvec(rng, -1, 1), b = rvec(rng, -1, 1);
        const V3d side = glm::normalize(glm::cross(b - a, runit(rng)));
        const double thin = log_uniform(rng, -5, -3) * glm::length(b - a);
        const V3d c = i % 2 == 0 ? b + thin * side : (a + b) * 0.5 + thin * side;  // needle, cap
        const V3f af = to_f(a), bf = to_f(b), cf = to_f(c);
        if (glm::length(glm::cross(bf - af, cf - af)) == 0) continue;
        const V3d target = a + rng.uniform(-0.05, 1.05) * (b - a) +
                           rng.uniform(-1, 2) * (c - (a + b) * 0.5) * double(i % 2);
        const V3d origin = rvec(rng, -4, 4);
        s.tris.push_back({to_f(origin), to_f(target - origin), af, bf, cf});
    }
}

void make_grazing(Scenario& s, Rng& rng, int n) {
    while (int(s.tris.size()) < n) {
        const V3d a = rvec(rng, -1, 1), b = rvec(rng, -1, 1), c = rvec(rng, -1, 1);
        const V3d nrm = glm::cross(b - a, c - a);
        if (glm::length(nrm) < 0.2) continue;
        const V3d un = glm::normalize(nrm);
        const V3d along = glm::normalize(glm::cross(un, runit(rng)));
        const double angle = log_uniform(rng, -5, -1);
        const double u = rng.uniform(-0.1, 1.1), v = rng.uniform(-0.1, 1.1) * (1 - u);
        const V3d target = a + u * (b - a) + v * (c - a);
        const V3d dir = along * std::cos(angle) - un * std::sin(angle);
        const V3d origin = target - rng.uniform(0.5, 3) * dir;
        s.tris.push_back({to_f(origin), to_f(dir), to_f(a), to_f(b), to_f(c)});
    }
}

// Closed convex meshes. Dyadic ones (vertices on a 1/64 grid) let rays pass exactly through an
// edge or a vertex in float; the icosphere and the general octahedra have arbitrary floats (the
// exact-target rays then use the dyadic boxes of the same scenario).
// Any positive half-axis lengths give a convex octahedron; dyadic ones are exact in float.
MeshData octahedron_mesh(Rng& rng, const V3d& offset, bool dyadic) {
    const exact::Mesh m = exact::octahedron(1);
    MeshData out;
    for (int i = 0; i < 6; ++i) {
        const double k = dyadic ? rng.integer(32, 128) / 64.0 : rng.uniform(0.5, 2);
        out.v.push_back(to_f(to_d(V3f(m.vertices[i])) * k + offset));
    }
    out.tri = m.triangles;
    return out;
}
MeshData dyadic_box(Rng& rng, const V3d& offset) {
    const exact::Mesh m = exact::cube(1);
    const V3d scale(rng.integer(32, 128) / 64.0, rng.integer(32, 128) / 64.0,
                    rng.integer(32, 128) / 64.0);
    const V3d shift = snap(rvec(rng, -0.5, 0.5), 1.0 / 64);
    MeshData out;
    for (const Vec3& v : m.vertices) out.v.push_back(to_f(to_d(V3f(v)) * scale + shift + offset));
    out.tri = m.triangles;
    return out;
}
// An icosahedron subdivided once (80 faces) on the unit sphere (make_icosphere), rounded to float
// before it is moved, whatever rt::Real is (so a double build makes the same cases).
MeshData icosphere_mesh(const V3d& offset) {
    const TriangleMesh ico = make_icosphere(1);
    MeshData out;
    for (const Vec3& p : ico.vertices) out.v.push_back(to_f(to_d(V3f(p)) + offset));
    for (const auto& t : ico.triangles) out.tri.push_back({int(t[0]), int(t[1]), int(t[2])});
    return out;
}

V3d face_normal(const MeshData& m, int f) {
    const V3d a = to_d(m.v[m.tri[f][0]]), b = to_d(m.v[m.tri[f][1]]), c = to_d(m.v[m.tri[f][2]]);
    return glm::normalize(glm::cross(b - a, c - a));
}

enum class Target { Surface, NearEdge, ExactEdge, NearVertex, ExactVertex };

// One ray from outside the mesh towards a target of the given kind. The direction leaves the
// target on the outer side of every face touching it, so the ray crosses the surface there
// properly (it is not tangent) and its origin is outside the convex mesh.
bool mesh_ray(Rng& rng, const MeshData& m, int mesh_index, Target kind, MeshCase& out) {
    const int f = rng.integer(0, int(m.tri.size()) - 1);
    const int e = rng.integer(0, 2);
    const int iu = m.tri[f][e], iv = m.tri[f][(e + 1) % 3], iw = m.tri[f][(e + 2) % 3];
    const V3d u = to_d(m.v[iu]), v = to_d(m.v[iv]), w = to_d(m.v[iw]);
    std::vector<int> faces;  // faces touching the target
    V3d target;
    const bool exact = kind == Target::ExactEdge || kind == Target::ExactVertex;
    if (kind == Target::Surface) {
        double bu = rng.uniform(0, 1), bv = rng.uniform(0, 1);
        if (bu + bv > 1) {
            bu = 1 - bu;
            bv = 1 - bv;
        }
        target = u + bu * (v - u) + bv * (w - u);
        faces = {f};
    } else if (kind == Target::NearEdge || kind == Target::ExactEdge) {
        for (int g = 0; g < int(m.tri.size()); ++g) {
            const auto& t = m.tri[g];
            const bool has_u = t[0] == iu || t[1] == iu || t[2] == iu;
            const bool has_v = t[0] == iv || t[1] == iv || t[2] == iv;
            if (has_u && has_v) faces.push_back(g);
        }
        double s = rng.integer(1, 15) / 16.0;
        target = u + s * (v - u);
        if (exact && !exact_in_float(target)) target = u + 0.5 * (v - u);
        if (kind == Target::NearEdge) {
            // Off the edge within one of its faces, by a relative 1e-8 .. 1e-3.
            const V3d inward = glm::normalize(glm::cross(face_normal(m, f), v - u));
            const double sign = rng.integer(0, 1) ? 1 : -1;
            target += sign * inward * glm::length(v - u) * log_uniform(rng, -8, -3);
        }
    } else {
        for (int g = 0; g < int(m.tri.size()); ++g) {
            const auto& t = m.tri[g];
            if (t[0] == iu || t[1] == iu || t[2] == iu) faces.push_back(g);
        }
        target = u;
        if (kind == Target::NearVertex) {
            const double bv = rng.uniform(0, 1), bw = rng.uniform(0, 1 - bv);
            const V3d into = glm::normalize(bv * (v - u) + bw * (w - u) + 1e-3 * (v - u));
            const double sign = rng.integer(0, 1) ? 1 : -1;
            target += sign * into * glm::length(v - u) * log_uniform(rng, -8, -3);
        }
    }
    if (exact && !exact_in_float(target)) return false;
    V3d avg(0);
    for (int g : faces) avg += face_normal(m, g);
    for (int attempt = 0; attempt < 20; ++attempt) {
        const V3d dir = glm::normalize(glm::normalize(avg) + 0.9 * runit(rng));
        bool outside = true;
        for (int g : faces) outside = outside && glm::dot(dir, face_normal(m, g)) > 0.05;
        if (!outside) continue;
        const double size = glm::length(v - u);
        V3d origin = target + dir * size * rng.uniform(1, 4);
        if (exact) origin = snap(origin, 1.0 / 64);
        const V3d d = target - origin;
        if (exact && (!exact_in_float(origin) || !exact_in_float(d))) continue;
        bool still = true;  // the snapped origin must stay outside every touching face
        for (int g : faces) still = still && glm::dot(-d, face_normal(m, g)) > 0;
        if (!still) continue;
        out = {to_f(origin), to_f(d), mesh_index};
        return true;
    }
    return false;
}

void make_mesh_scenario(Scenario& s, Rng& rng, int n, const std::vector<Target>& kinds,
                        double offset_magnitude, bool with_icosphere) {
    const int kMeshes = 24;
    for (int i = 0; i < kMeshes; ++i) {
        // Dyadic offsets keep dyadic meshes exact in float (1e5 < 2^17: spacing 2^-7 there).
        const V3d offset = offset_magnitude > 0
                               ? snap(rvec(rng, -offset_magnitude, offset_magnitude), 1.0)
                               : V3d(0);
        const int kind = i % 3;
        if (kind == 2 && with_icosphere)
            s.meshes.push_back(icosphere_mesh(offset));
        else if (kind == 1)
            s.meshes.push_back(dyadic_box(rng, offset));
        else
            s.meshes.push_back(octahedron_mesh(rng, offset, !with_icosphere));
    }
    int i = 0;
    while (int(s.rays.size()) < n) {
        const int mi = rng.integer(0, kMeshes - 1);
        MeshCase c;
        if (mesh_ray(rng, s.meshes[mi], mi, kinds[i % kinds.size()], c)) {
            s.rays.push_back(c);
            ++i;
        }
    }
}

void make_spheres(Scenario& s, Rng& rng, int n, const std::string& key) {
    while (int(s.spheres.size()) < n) {
        SphereCase c{};
        if (key == "sphere-random" || key == "sphere-offset-1e3" || key == "sphere-offset-1e5") {
            const double off = key == "sphere-random" ? 0 : key == "sphere-offset-1e3" ? 1e3 : 1e5;
            const V3d offset = rvec(rng, -off, off);
            const V3d center = rvec(rng, -5, 5) + offset;
            const double r = rng.uniform(0.5, 2);
            const V3d o = rvec(rng, -10, 10) + offset;
            const V3d target = center + rvec(rng, -1.3, 1.3) * r;
            c = {to_f(o), to_f((target - o) * rng.uniform(0.5, 2)), to_f(center), float(r)};
        } else if (key == "sphere-grazing") {
            // Lines passing the centre at r (1 +- 1e-7 .. 1e-2): near tangent.
            const V3d center = rvec(rng, -5, 5);
            const double r = rng.uniform(0.5, 2);
            const double dist = rng.uniform(5, 20);
            const V3d o = center + runit(rng) * dist;
            const V3d to_c = glm::normalize(center - o);
            const V3d side = glm::normalize(glm::cross(to_c, runit(rng)));
            const double off = r * (1 + (rng.integer(0, 1) ? 1 : -1) * log_uniform(rng, -7, -2));
            const double sin_a = off / dist;  // the line passes the centre at distance off
            const V3d dir = to_c * std::sqrt(1 - sin_a * sin_a) + side * sin_a;
            c = {to_f(o), to_f(dir * rng.uniform(0.5, 2)), to_f(center), float(r)};
        } else if (key == "far-small") {
            // Radius 1 at 1e3 .. 3e4; the line passes within 0.95 r or beyond 1.05 r of the
            // centre: clear hits and clear misses, no ties.
            const V3d o = rvec(rng, -1, 1);
            const V3d center = o + runit(rng) * log_uniform(rng, 3, 4.5);
            const V3d to_c = glm::normalize(center - o);
            const V3d side = glm::normalize(glm::cross(to_c, runit(rng)));
            const double off = rng.integer(0, 1) ? rng.uniform(0, 0.95) : rng.uniform(1.05, 1.5);
            c = {to_f(o), to_f(center + side * off - o), to_f(center), 1.0f};
        } else if (key == "sphere-inside") {
            // The origin anywhere inside (up to 0.95 r from the centre), any direction: every ray
            // leaves through the sphere, half of them with the centre behind the origin.
            const V3d center = rvec(rng, -5, 5);
            const double r = rng.uniform(0.5, 2);
            const V3d o = center + runit(rng) * (r * rng.uniform(0, 0.95));
            c = {to_f(o), to_f(runit(rng) * rng.uniform(0.5, 2)), to_f(center), float(r)};
        } else {  // large-near: radius 1e3 .. 1e4, origin 1e-2 .. 1 above the surface
            const V3d center = rvec(rng, -10, 10);
            const double r = log_uniform(rng, 3, 4);
            const V3d up = runit(rng);
            const V3d o = center + up * (r + log_uniform(rng, -2, 0));
            const V3d dir = glm::normalize(-up * rng.uniform(rng.integer(0, 4) ? 0.05 : -0.05, 1) +
                                           runit(rng) * 0.5);
            c = {to_f(o), to_f(dir), to_f(center), float(r)};
        }
        s.spheres.push_back(c);
    }
}

}  // namespace

std::vector<Scenario> make_scenarios(std::uint64_t seed, int n) {
    std::vector<Scenario> out;
    std::uint64_t k = 0;
    for (const ScenarioInfo& info : scenarios()) {
        Scenario s{info, {}, {}, {}, {}};
        Rng rng(seed * 1000003 + (k++));  // each scenario its own stream
        const std::string& key = info.key;
        if (key == "random")
            make_random(s, rng, n);
        else if (key == "sliver")
            make_sliver(s, rng, n);
        else if (key == "grazing")
            make_grazing(s, rng, n);
        else if (key == "near-edge")
            make_mesh_scenario(s, rng, n, {Target::NearEdge}, 0, true);
        else if (key == "through-edge")
            make_mesh_scenario(s, rng, n, {Target::ExactEdge}, 0, false);
        else if (key == "near-vertex")
            make_mesh_scenario(s, rng, n, {Target::NearVertex}, 0, true);
        else if (key == "through-vertex")
            make_mesh_scenario(s, rng, n, {Target::ExactVertex}, 0, false);
        else if (key == "offset-1e3" || key == "offset-1e5")
            make_mesh_scenario(s, rng, n,
                               {Target::Surface, Target::NearEdge, Target::ExactEdge,
                                Target::NearVertex, Target::ExactVertex},
                               key == "offset-1e3" ? 1e3 : 1e5, true);
        else
            make_spheres(s, rng, n, key);
        out.push_back(std::move(s));
    }
    return out;
}

}  // namespace rt::bench::detail
