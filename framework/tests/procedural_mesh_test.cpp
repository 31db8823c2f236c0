// Tests of the procedural meshes (framework/geometry/procedural_mesh.h): exact triangle counts,
// closed and outward-facing surfaces, bounded terrain, bit-for-bit determinism, and the choice
// of resolution by make_procedural_mesh.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>
#include <stdexcept>
#include <utility>

#include "geometry/procedural_mesh.h"

namespace {

constexpr double kPi = 3.14159265358979323846;

// Every index in range and the per-vertex arrays either empty or parallel to the vertices.
void expect_well_formed(const rt::TriangleMesh& mesh) {
    for (const auto& t : mesh.triangles)
        for (std::uint32_t v : t) ASSERT_LT(v, mesh.vertices.size());
    EXPECT_TRUE(mesh.normals.empty() || mesh.normals.size() == mesh.vertices.size());
    EXPECT_TRUE(mesh.uvs.empty() || mesh.uvs.size() == mesh.vertices.size());
    for (const rt::Vec3& p : mesh.vertices) ASSERT_TRUE(rt::all_finite(p));
    for (const rt::Vec3& n : mesh.normals) {
        ASSERT_TRUE(rt::all_finite(n));
        EXPECT_NEAR(std::sqrt(double(glm::dot(n, n))), 1.0, 1e-5);
    }
}

// Vertex ids after merging vertices with bit-identical positions (the torus repeats its first
// ring and side so that its uvs need not wrap).
std::vector<std::uint32_t> weld(const rt::TriangleMesh& mesh) {
    std::map<std::array<rt::Real, 3>, std::uint32_t> first;
    std::vector<std::uint32_t> id(mesh.vertices.size());
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        const rt::Vec3& p = mesh.vertices[i];
        id[i] = first.emplace(std::array<rt::Real, 3>{p.x, p.y, p.z}, std::uint32_t(first.size()))
                    .first->second;
    }
    return id;
}

// A closed, consistently oriented 2-manifold uses every directed edge (a, b) exactly once and
// its reverse (b, a) exactly once; no triangle is degenerate after welding.
void expect_closed_and_consistent(const rt::TriangleMesh& mesh) {
    std::vector<std::uint32_t> id = weld(mesh);
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (const auto& t : mesh.triangles) {
        std::uint32_t v[3] = {id[t[0]], id[t[1]], id[t[2]]};
        ASSERT_TRUE(v[0] != v[1] && v[1] != v[2] && v[0] != v[2]) << "degenerate triangle";
        for (int k = 0; k < 3; ++k) ++directed[{v[k], v[(k + 1) % 3]}];
    }
    for (const auto& [edge, uses] : directed) {
        ASSERT_EQ(uses, 1) << "edge " << edge.first << "-" << edge.second << " used " << uses
                           << " times";
        auto reverse = directed.find({edge.second, edge.first});
        ASSERT_NE(reverse, directed.end())
            << "edge " << edge.first << "-" << edge.second << " is a border";
    }
}

// Signed volume by the divergence theorem: positive when the triangles face outwards.
double signed_volume(const rt::TriangleMesh& mesh) {
    double volume = 0;
    for (const auto& t : mesh.triangles) {
        glm::dvec3 a(mesh.vertices[t[0]]), b(mesh.vertices[t[1]]), c(mesh.vertices[t[2]]);
        volume += glm::dot(a, glm::cross(b, c)) / 6;
    }
    return volume;
}

glm::dvec3 face_normal(const rt::TriangleMesh& mesh, std::size_t i) {
    const auto& t = mesh.triangles[i];
    glm::dvec3 a(mesh.vertices[t[0]]), b(mesh.vertices[t[1]]), c(mesh.vertices[t[2]]);
    return glm::cross(b - a, c - a);
}

bool same_bits(const rt::TriangleMesh& x, const rt::TriangleMesh& y) {
    auto equal = [](const auto& u, const auto& v) {
        return u.size() == v.size() &&
               (u.empty() || std::memcmp(u.data(), v.data(), u.size() * sizeof(u[0])) == 0);
    };
    return equal(x.vertices, y.vertices) && equal(x.triangles, y.triangles) &&
           equal(x.normals, y.normals) && equal(x.uvs, y.uvs);
}

TEST(ProceduralMesh, IcosphereCountsAndClosedness) {
    for (int s = 0; s <= 4; ++s) {
        rt::TriangleMesh mesh = rt::make_icosphere(s, rt::Real(2));
        std::size_t expected = 20;
        for (int k = 0; k < s; ++k) expected *= 4;
        EXPECT_EQ(mesh.triangles.size(), expected) << "subdivisions " << s;
        EXPECT_EQ(mesh.vertices.size(), expected / 2 + 2)
            << "shared vertices (Euler: V = F / 2 + 2)";
        expect_well_formed(mesh);
        expect_closed_and_consistent(mesh);
        EXPECT_TRUE(mesh.uvs.empty());
        for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
            EXPECT_NEAR(double(glm::length(mesh.vertices[v])), 2.0, 1e-5);  // on the sphere
            EXPECT_GT(glm::dot(mesh.normals[v], mesh.vertices[v]), 0);      // pointing out
        }
    }
}

TEST(ProceduralMesh, IcosphereFacesOutwardsWithTheSphereVolume) {
    const double r = 1.5, sphere = 4.0 / 3.0 * kPi * r * r * r;
    double previous = 0;
    for (int s = 0; s <= 5; ++s) {
        rt::TriangleMesh mesh = rt::make_icosphere(s, rt::Real(r));
        double volume = signed_volume(mesh);
        EXPECT_GT(volume, 0) << "inward-facing triangles, subdivisions " << s;
        EXPECT_LT(volume, sphere) << "an inscribed polyhedron is smaller than its sphere";
        EXPECT_GT(volume, previous) << "finer meshes fill more of the sphere";
        previous = volume;
        for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {  // every face, not just the sum
            glm::dvec3 center(mesh.vertices[mesh.triangles[i][0]]);
            ASSERT_GT(glm::dot(face_normal(mesh, i), center), 0) << "triangle " << i;
        }
    }
    EXPECT_NEAR(previous / sphere, 1.0, 0.002);  // 20480 triangles: within 0.2%
}

TEST(ProceduralMesh, TorusCountsClosednessAndVolume) {
    const std::pair<int, int> sizes[] = {{3, 3}, {8, 5}, {40, 20}, {128, 64}};
    for (auto [rings, sides] : sizes) {
        rt::TriangleMesh mesh = rt::make_torus(rings, sides, rt::Real(2), rt::Real(0.5));
        EXPECT_EQ(mesh.triangles.size(), std::size_t(2 * rings * sides));
        expect_well_formed(mesh);
        ASSERT_EQ(mesh.uvs.size(), mesh.vertices.size());
        expect_closed_and_consistent(mesh);
        EXPECT_GT(signed_volume(mesh), 0) << rings << " x " << sides;
    }
    rt::TriangleMesh fine = rt::make_torus(256, 128, rt::Real(2), rt::Real(0.5));
    const double torus = 2 * kPi * kPi * 2 * 0.5 * 0.5;  // 2 pi^2 R r^2
    EXPECT_NEAR(signed_volume(fine) / torus, 1.0, 0.002);
    // Normals point away from the tube's centre line, and uvs cover [0, 1]^2.
    for (std::size_t v = 0; v < fine.vertices.size(); ++v) {
        glm::dvec3 p(fine.vertices[v]);
        glm::dvec3 axis_point = glm::normalize(glm::dvec3(p.x, 0, p.z)) * 2.0;
        ASSERT_GT(glm::dot(glm::dvec3(fine.normals[v]), p - axis_point), 0.49) << v;
        ASSERT_TRUE(fine.uvs[v].x >= 0 && fine.uvs[v].x <= 1 && fine.uvs[v].y >= 0 &&
                    fine.uvs[v].y <= 1);
    }
    EXPECT_EQ(fine.uvs.back(), rt::Vec2(1, 1));
}

TEST(ProceduralMesh, TerrainIsBoundedAndFacesUp) {
    for (std::uint64_t seed : {1u, 2u, 12345u}) {
        rt::TriangleMesh mesh = rt::make_terrain(37, 23, seed, rt::Real(0.4));
        EXPECT_EQ(mesh.triangles.size(), 2u * 37 * 23);
        EXPECT_EQ(mesh.vertices.size(), 38u * 24);
        expect_well_formed(mesh);
        ASSERT_EQ(mesh.uvs.size(), mesh.vertices.size());
        rt::Real low = 1, high = 0;
        for (const rt::Vec3& p : mesh.vertices) {
            ASSERT_TRUE(p.x >= -1 && p.x <= 1 && p.z >= -1 && p.z <= 1);
            ASSERT_TRUE(p.y >= 0 && p.y <= rt::Real(0.4)) << p.y;
            low = std::min(low, p.y);
            high = std::max(high, p.y);
        }
        EXPECT_GT(high - low, rt::Real(0.1)) << "a terrain, not a flat plane";
        for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
            ASSERT_GT(face_normal(mesh, i).y, 0);
        for (const rt::Vec3& n : mesh.normals) ASSERT_GT(n.y, 0);
        EXPECT_EQ(mesh.vertices.front().x, -1);
        EXPECT_EQ(mesh.vertices.back().z, 1);
    }
    rt::TriangleMesh flat = rt::make_terrain(4, 4, 7, rt::Real(0));
    for (const rt::Vec3& p : flat.vertices) EXPECT_EQ(p.y, 0);
}

TEST(ProceduralMesh, SoupCountsSizesAndBounds) {
    rt::TriangleMesh soup = rt::make_triangle_soup(5000, 9, rt::Real(0.1));
    EXPECT_EQ(soup.triangles.size(), 5000u);
    EXPECT_EQ(soup.vertices.size(), 15000u);
    expect_well_formed(soup);
    double edges = 0;
    for (std::size_t i = 0; i < soup.triangles.size(); ++i) {
        const auto& t = soup.triangles[i];
        EXPECT_EQ(t[0], 3 * i);
        for (int k = 0; k < 3; ++k) {
            const rt::Vec3& p = soup.vertices[t[std::size_t(k)]];
            ASSERT_TRUE(p.x >= -1 && p.x <= 1 && p.y >= -1 && p.y <= 1 && p.z >= -1 && p.z <= 1);
            edges +=
                glm::length(glm::dvec3(soup.vertices[t[std::size_t((k + 1) % 3)]]) - glm::dvec3(p));
        }
        ASSERT_GT(glm::length(face_normal(soup, i)), 0);
    }
    double mean_edge = edges / (3.0 * 5000);
    EXPECT_GT(mean_edge, 0.07);
    EXPECT_LT(mean_edge, 0.13);
    EXPECT_TRUE(rt::make_triangle_soup(0, 1).triangles.empty());
}

TEST(ProceduralMesh, SameSeedSameBitsOtherSeedOtherMesh) {
    EXPECT_TRUE(same_bits(rt::make_terrain(20, 30, 5), rt::make_terrain(20, 30, 5)));
    EXPECT_TRUE(same_bits(rt::make_triangle_soup(1000, 5), rt::make_triangle_soup(1000, 5)));
    EXPECT_TRUE(same_bits(rt::make_icosphere(3), rt::make_icosphere(3)));
    EXPECT_TRUE(same_bits(rt::make_torus(30, 12), rt::make_torus(30, 12)));
    EXPECT_TRUE(same_bits(rt::make_procedural_mesh("terrain", 999, 42),
                          rt::make_procedural_mesh("terrain", 999, 42)));
    EXPECT_FALSE(same_bits(rt::make_terrain(20, 30, 5), rt::make_terrain(20, 30, 6)));
    EXPECT_FALSE(same_bits(rt::make_triangle_soup(1000, 5), rt::make_triangle_soup(1000, 6)));
    EXPECT_FALSE(same_bits(rt::make_procedural_mesh("soup", 10, 1),
                           rt::make_procedural_mesh("soup", 10, 2)));
}

// A few coordinates pinned to values computed independently (double-precision formulas, by
// hand): catches a change of formula that determinism alone would not.
TEST(ProceduralMesh, KnownCoordinates) {
    rt::TriangleMesh torus = rt::make_torus(4, 4, rt::Real(1), rt::Real(0.25));
    // Row 0 (theta = 0, direction +x), sides at phi = 0, 90, 180 degrees.
    EXPECT_EQ(torus.vertices[0], rt::Vec3(rt::Real(1.25), 0, 0));
    EXPECT_NEAR(torus.vertices[1].x, 1, 1e-7);
    EXPECT_EQ(torus.vertices[1].y, rt::Real(0.25));
    EXPECT_EQ(torus.vertices[2].x, rt::Real(0.75));
    // Row 1 (theta = 90 degrees, direction +z).
    EXPECT_NEAR(torus.vertices[5].x, 0, 1e-7);
    EXPECT_EQ(torus.vertices[5].z, rt::Real(1.25));
    rt::TriangleMesh ico = rt::make_icosphere(0);
    const double phi = (1 + std::sqrt(5.0)) / 2, scale = 1 / std::sqrt(1 + phi * phi);
    for (const rt::Vec3& p : ico.vertices) {  // every coordinate is 0, +-scale or +-phi*scale
        for (int k = 0; k < 3; ++k) {
            double c = std::fabs(double(p[k]));
            EXPECT_TRUE(c == 0 || std::fabs(c - scale) < 1e-7 || std::fabs(c - phi * scale) < 1e-7)
                << c;
        }
    }
}

// FNV-1a over the mesh rounded to float (the same bits whether Real is float or double).
std::uint64_t fingerprint(const rt::TriangleMesh& mesh) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    auto add = [&h](const void* data, std::size_t size) {
        const auto* bytes = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i) h = (h ^ bytes[i]) * 0x100000001b3ull;
    };
    auto add_reals = [&](const auto& vectors, int n) {
        for (const auto& v : vectors)
            for (int k = 0; k < n; ++k) {
                float f = float(v[k]);
                add(&f, sizeof f);
            }
    };
    add_reals(mesh.vertices, 3);
    add_reals(mesh.normals, 3);
    add_reals(mesh.uvs, 2);
    for (const auto& t : mesh.triangles) add(t.data(), sizeof t);
    return h;
}

// The meshes are pinned bit for bit: benchmarks and reference images built on them must not
// change with the compiler, the C library or the machine (the generators use no libm functions
// and no standard-library distributions). The sizes are exact in float and double, so both
// presets give the same bits. A deliberate change of a generator updates these.
TEST(ProceduralMesh, PinnedBitForBit) {
    EXPECT_EQ(fingerprint(rt::make_icosphere(3)), 0x9c2cf0e04fee7c4dull);
    EXPECT_EQ(fingerprint(rt::make_torus(24, 12, 1, rt::Real(0.25))), 0xc7ff33137d7e51fbull);
    EXPECT_EQ(fingerprint(rt::make_terrain(16, 9, 77, rt::Real(0.25))), 0x67916284c02e0132ull);
    EXPECT_EQ(fingerprint(rt::make_triangle_soup(100, 77, rt::Real(0.125))), 0xa76d6d482ec61b40ull);
}

TEST(ProceduralMesh, ChoosesTheSmallestResolution) {
    for (std::size_t n : {0u, 1u, 19u, 20u, 21u, 80u, 81u, 1000u, 20000u, 123457u}) {
        rt::ProceduralResolution ico = rt::procedural_resolution("icosphere", n);
        EXPECT_GE(ico.triangles, std::max<std::size_t>(n, 1));
        EXPECT_TRUE(ico.a == 0 || ico.triangles / 4 < n) << n;
        EXPECT_EQ(rt::make_procedural_mesh("icosphere", n).triangles.size(), ico.triangles);

        rt::ProceduralResolution torus = rt::procedural_resolution("torus", n);
        EXPECT_EQ(torus.triangles, std::size_t(2 * torus.a * torus.b));
        EXPECT_GE(torus.triangles, n);
        EXPECT_TRUE(torus.a == 3 || std::size_t(2 * (torus.a - 1) * torus.b) < n) << n;
        EXPECT_GE(torus.b, 3);
        if (n >= 1000) {
            EXPECT_NEAR(double(torus.a) / torus.b, 2.0, 0.5);
        }
        EXPECT_EQ(rt::make_procedural_mesh("torus", n).triangles.size(), torus.triangles);

        rt::ProceduralResolution terrain = rt::procedural_resolution("terrain", n);
        EXPECT_EQ(terrain.triangles, std::size_t(2 * terrain.a * terrain.b));
        EXPECT_GE(terrain.triangles, std::max<std::size_t>(n, 1));
        EXPECT_TRUE(terrain.a == 1 || std::size_t(2 * (terrain.a - 1) * terrain.b) < n) << n;
        EXPECT_EQ(rt::make_procedural_mesh("terrain", n, 3).triangles.size(), terrain.triangles);

        EXPECT_EQ(rt::make_procedural_mesh("soup", n, 3).triangles.size(),
                  std::max<std::size_t>(n, 1));
    }
    EXPECT_EQ(rt::procedural_resolution("icosphere", 81).a, 2);  // 320 triangles
    EXPECT_EQ(rt::procedural_resolution("icosphere", 80).a, 1);
}

TEST(ProceduralMesh, RejectsUnknownNamesAndAbsurdSizes) {
    try {
        rt::make_procedural_mesh("cube", 100);
        FAIL() << "no exception";
    } catch (const std::invalid_argument& e) {
        std::string message = e.what();
        EXPECT_NE(message.find("\"cube\""), std::string::npos) << message;
        for (const std::string& known : rt::procedural_shapes())
            EXPECT_NE(message.find("\"" + known + "\""), std::string::npos) << message;
    }
    EXPECT_THROW(rt::make_procedural_mesh("", 100), std::invalid_argument);
    EXPECT_THROW(rt::make_procedural_mesh("Torus", 100), std::invalid_argument);
    EXPECT_THROW(rt::make_procedural_mesh("soup", rt::kMaxProceduralTriangles + 1),
                 std::invalid_argument);
    EXPECT_THROW(rt::make_procedural_mesh("icosphere", 6'000'000),
                 std::invalid_argument);  // needs 20971520
    EXPECT_THROW(rt::make_icosphere(-1), std::invalid_argument);
    EXPECT_THROW(rt::make_icosphere(rt::kMaxIcosphereSubdivisions + 1), std::invalid_argument);
    EXPECT_THROW(rt::make_icosphere(1, 0), std::invalid_argument);
    EXPECT_THROW(rt::make_torus(2, 8), std::invalid_argument);
    EXPECT_THROW(rt::make_torus(100000, 100000), std::invalid_argument);
    EXPECT_THROW(rt::make_torus(8, 8, 1, 1), std::invalid_argument);
    EXPECT_THROW(rt::make_terrain(0, 8, 1), std::invalid_argument);
    EXPECT_THROW(rt::make_terrain(8, 8, 1, -1), std::invalid_argument);
    EXPECT_THROW(rt::make_triangle_soup(10, 1, std::numeric_limits<rt::Real>::quiet_NaN()),
                 std::invalid_argument);
    EXPECT_THROW(rt::make_triangle_soup(rt::kMaxProceduralTriangles + 1, 1), std::invalid_argument);
}

}  // namespace
