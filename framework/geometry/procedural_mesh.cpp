// Procedural meshes (procedural_mesh.h). Everything is computed in double with +, -, *, / and
// sqrt only (IEEE operations, rounded the same way everywhere) and rounded to Real at the end, so
// a mesh is the same bit for bit on every machine: no std::sin (libm versions differ in the last
// bit) and no std::uniform_*_distribution (its algorithm is up to the standard library).
#include "geometry/procedural_mesh.h"

#include "geometry/height_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/split_mix64.h"

namespace rt {

namespace {

using D3 = glm::dvec3;

constexpr double kTwoPi = 6.283185307179586476925286766559;

// ---- deterministic helpers ------------------------------------------------------------------

// A hash of (seed, i, j) for value noise: the first output of a generator seeded with all three.
std::uint64_t hash3(std::uint64_t seed, std::int64_t i, std::int64_t j) {
    return SplitMix64::hash(seed ^ (std::uint64_t(i) * 0xD1B54A32D192ED03ull) ^
                            (std::uint64_t(j) * 0xABC98388FB8FAC03ull));
}

// The Taylor coefficients (-1)^k / n! of sin (odd n) and cos (even n) up to n = 18, folded by
// the compiler.
struct TaylorCoefficients {
    double c[19] = {};
    constexpr TaylorCoefficients() {
        double factorial = 1;
        for (int n = 1; n <= 18; ++n) {
            factorial *= n;
            c[n] = ((n / 2) % 2 ? -1 : 1) / factorial;
        }
    }
};
constexpr TaylorCoefficients kTaylor;

// sin(r) and cos(r) for |r| <= pi/4 by their Taylor series in Horner form (the first omitted
// terms are below 1e-19, beneath double's rounding).
double sin_small(double r) {
    double r2 = r * r, sum = 0;
    for (int n = 17; n >= 3; n -= 2) sum = (sum + kTaylor.c[n]) * r2;
    return r + r * sum;
}
double cos_small(double r) {
    double r2 = r * r, sum = 0;
    for (int n = 18; n >= 2; n -= 2) sum = (sum + kTaylor.c[n]) * r2;
    return 1 + sum;
}

// sin and cos of x (radians, |x| up to a few thousand) from basic arithmetic only: reduce by the
// nearest multiple k of pi/2 (pi/2 split in two parts so the reduction stays accurate), then pick
// the quadrant.
void sin_cos(double x, double& s, double& c) {
    constexpr double kHalfPiHi = 1.57079632679489655800e+00;  // pi/2 rounded to double
    constexpr double kHalfPiLo = 6.12323399573676603587e-17;  // pi/2 - kHalfPiHi
    double k = std::nearbyint(x / kHalfPiHi);
    double r = (x - k * kHalfPiHi) - k * kHalfPiLo;
    double sr = sin_small(r), cr = cos_small(r);
    long quadrant = static_cast<long>(k) & 3;
    switch (quadrant) {
        case 0:
            s = sr;
            c = cr;
            break;
        case 1:
            s = cr;
            c = -sr;
            break;
        case 2:
            s = -sr;
            c = -cr;
            break;
        default:
            s = -cr;
            c = sr;
            break;
    }
}

D3 unit(const D3& v) {
    return v / std::sqrt(glm::dot(v, v));
}

Vec3 to_real(const D3& v) {
    return Vec3(Real(v.x), Real(v.y), Real(v.z));
}

void require(bool ok, const std::string& message) {
    if (!ok) throw std::invalid_argument(message);
}

void require_positive(double value, const char* what, const char* function) {
    require(std::isfinite(value) && value > 0,
            std::string(function) + ": " + what + " must be a finite number > 0");
}

void require_count(double triangles, const char* function) {
    require(
        triangles <= double(kMaxProceduralTriangles),
        std::string(function) + ": " + std::to_string(static_cast<unsigned long long>(triangles)) +
            " triangles, more than the " + std::to_string(kMaxProceduralTriangles) + " allowed");
}

// ---- resolutions ----------------------------------------------------------------------------

// The smallest whole k >= 0 with k * k >= n (exact, unlike std::sqrt on large n).
std::size_t ceil_sqrt(std::size_t n) {
    std::size_t k = static_cast<std::size_t>(std::sqrt(double(n)));
    while (k * k < n) ++k;
    while (k > 0 && (k - 1) * (k - 1) >= n) --k;
    return k;
}

std::size_t ceil_div(std::size_t a, std::size_t b) {
    return (a + b - 1) / b;
}

const char* const kShapeNames[] = {"icosphere", "torus", "terrain", "soup"};

std::string known_shapes() {
    std::string out;
    for (std::size_t i = 0; i < std::size(kShapeNames); ++i)
        out += std::string(i == 0                            ? ""
                           : i + 1 == std::size(kShapeNames) ? " or "
                                                             : ", ") +
               "\"" + kShapeNames[i] + "\"";
    return out;
}

}  // namespace

// ---- icosphere ------------------------------------------------------------------------------

TriangleMesh make_icosphere(int subdivisions, Real radius) {
    require(subdivisions >= 0 && subdivisions <= kMaxIcosphereSubdivisions,
            "make_icosphere: subdivisions must be 0.." + std::to_string(kMaxIcosphereSubdivisions) +
                ", got " + std::to_string(subdivisions));
    require_positive(double(radius), "radius", "make_icosphere");

    // The icosahedron's corners are the cyclic permutations of (0, +-1, +-phi); its faces are the
    // triples of corners at mutual distance 2 (the edge length), oriented to face outwards.
    const double phi = (1 + std::sqrt(5.0)) / 2;
    std::vector<D3> points;
    for (int axis = 0; axis < 3; ++axis)
        for (double a : {-1.0, 1.0})
            for (double b : {-phi, phi}) {
                D3 p(0);
                p[(axis + 1) % 3] = a;
                p[(axis + 2) % 3] = b;
                points.push_back(p);
            }
    auto is_edge = [&](std::size_t i, std::size_t j) {
        D3 d = points[i] - points[j];
        return glm::dot(d, d) < 5;  // edges: 4; the next distance is 2 phi, squared 10.5
    };
    std::vector<std::array<std::uint32_t, 3>> faces;
    for (std::uint32_t i = 0; i < 12; ++i)
        for (std::uint32_t j = i + 1; j < 12; ++j)
            for (std::uint32_t k = j + 1; k < 12; ++k) {
                if (!is_edge(i, j) || !is_edge(j, k) || !is_edge(i, k)) continue;
                D3 n = glm::cross(points[j] - points[i], points[k] - points[i]);
                if (glm::dot(n, points[i] + points[j] + points[k]) > 0)
                    faces.push_back({i, j, k});
                else
                    faces.push_back({i, k, j});
            }
    for (D3& p : points) p = unit(p);

    // Each subdivision splits every triangle into four at its edge midpoints, pushed out onto
    // the sphere. A midpoint is shared by the two triangles of its edge.
    // The midpoints made so far are kept per edge in a chain starting at the edge's smaller
    // vertex (a handful per vertex; much faster than a hash map at millions of edges).
    constexpr std::uint32_t kNone = UINT32_MAX;
    for (int level = 0; level < subdivisions; ++level) {
        std::vector<std::uint32_t> first(points.size(), kNone);
        struct Edge {
            std::uint32_t other, middle, next;
        };
        std::vector<Edge> edges;
        edges.reserve(faces.size() * 3 / 2);
        points.reserve(points.size() + faces.size() * 3 / 2);
        auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            std::uint32_t low = std::min(a, b), high = std::max(a, b);
            for (std::uint32_t e = first[low]; e != kNone; e = edges[e].next)
                if (edges[e].other == high) return edges[e].middle;
            auto middle = std::uint32_t(points.size());
            points.push_back(unit(points[a] + points[b]));
            edges.push_back({high, middle, first[low]});
            first[low] = std::uint32_t(edges.size() - 1);
            return middle;
        };
        std::vector<std::array<std::uint32_t, 3>> finer;
        finer.reserve(faces.size() * 4);
        for (const auto& [a, b, c] : faces) {
            std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
            finer.push_back({a, ab, ca});
            finer.push_back({ab, b, bc});
            finer.push_back({ca, bc, c});
            finer.push_back({ab, bc, ca});
        }
        faces = std::move(finer);
    }

    TriangleMesh mesh;
    mesh.triangles = std::move(faces);
    mesh.vertices.reserve(points.size());
    mesh.normals.reserve(points.size());
    for (const D3& p : points) {
        mesh.vertices.push_back(to_real(p * double(radius)));
        mesh.normals.push_back(to_real(p));
    }
    return mesh;
}

// ---- torus ----------------------------------------------------------------------------------

TriangleMesh make_torus(int rings, int sides, Real major_radius, Real minor_radius) {
    require(rings >= 3 && sides >= 3, "make_torus: rings and sides must be >= 3, got " +
                                          std::to_string(rings) + " and " + std::to_string(sides));
    require_count(2.0 * rings * sides, "make_torus");
    require_positive(double(major_radius), "major_radius", "make_torus");
    require_positive(double(minor_radius), "minor_radius", "make_torus");
    require(minor_radius < major_radius, "make_torus: minor_radius must be below major_radius");

    // Grid point (i, j): angle theta = 2 pi i / rings around +y, phi = 2 pi j / sides around the
    // tube. Row i = rings and column j = sides repeat row and column 0 exactly (same bits), so the
    // uvs can run from 0 to 1 without wrapping while the surface stays closed.
    const std::size_t columns = std::size_t(sides) + 1;
    auto index = [&](int i, int j) {
        return std::uint32_t(std::size_t(i) * columns + std::size_t(j));
    };
    std::vector<double> cos_theta(std::size_t(rings) + 1), sin_theta(std::size_t(rings) + 1);
    std::vector<double> cos_phi(columns), sin_phi(columns);
    for (int i = 0; i < rings; ++i)
        sin_cos(kTwoPi * i / rings, sin_theta[std::size_t(i)], cos_theta[std::size_t(i)]);
    for (int j = 0; j < sides; ++j)
        sin_cos(kTwoPi * j / sides, sin_phi[std::size_t(j)], cos_phi[std::size_t(j)]);
    cos_theta[std::size_t(rings)] = cos_theta[0];
    sin_theta[std::size_t(rings)] = sin_theta[0];
    cos_phi[std::size_t(sides)] = cos_phi[0];
    sin_phi[std::size_t(sides)] = sin_phi[0];

    TriangleMesh mesh;
    const std::size_t count = (std::size_t(rings) + 1) * columns;
    mesh.vertices.reserve(count);
    mesh.normals.reserve(count);
    mesh.uvs.reserve(count);
    const double big = double(major_radius), small = double(minor_radius);
    for (int i = 0; i <= rings; ++i)
        for (int j = 0; j <= sides; ++j) {
            D3 out(cos_theta[std::size_t(i)], 0, sin_theta[std::size_t(i)]);  // from the axis
            D3 normal = out * cos_phi[std::size_t(j)] + D3(0, sin_phi[std::size_t(j)], 0);
            mesh.vertices.push_back(to_real(out * big + normal * small));
            mesh.normals.push_back(to_real(normal));
            mesh.uvs.push_back(Vec2(Real(double(i) / rings), Real(double(j) / sides)));
        }
    // Moving along j turns the tube's surface towards +y, along i around the axis; (i, j) ->
    // (i, j + 1) -> (i + 1, j + 1) is counter-clockwise seen from outside the tube.
    mesh.triangles.reserve(2 * std::size_t(rings) * std::size_t(sides));
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < sides; ++j) {
            std::uint32_t a = index(i, j), b = index(i, j + 1), c = index(i + 1, j + 1),
                          d = index(i + 1, j);
            mesh.triangles.push_back({a, b, c});
            mesh.triangles.push_back({a, c, d});
        }
    return mesh;
}

// ---- terrain --------------------------------------------------------------------------------

namespace {

// A height in [0, 1] at (x, z): the average of a few seeded plane waves and of smoothly
// interpolated random values on an 8 x 8 lattice, each in [-1, 1], mapped to [0, 1].
class HeightField {
  public:
    explicit HeightField(std::uint64_t seed) : seed_(seed) {
        SplitMix64 random(seed);
        for (Wave& w : waves_) {
            double s, c;
            sin_cos(random.between(0, kTwoPi), s, c);
            double frequency = random.between(2, 7);
            w.kx = c * frequency;
            w.kz = s * frequency;
            w.phase = random.between(0, kTwoPi);
            w.weight = random.between(0.3, 1);
        }
    }

    double operator()(double x, double z) const {
        double sum = 0, weights = 0;
        for (const Wave& w : waves_) {
            double s, c;
            sin_cos(w.kx * x + w.kz * z + w.phase, s, c);
            sum += w.weight * s;
            weights += w.weight;
        }
        sum += kNoiseWeight * noise(x, z);
        weights += kNoiseWeight;
        double f = (sum / weights + 1) / 2;
        return std::clamp(f, 0.0, 1.0);
    }

  private:
    struct Wave {
        double kx = 0, kz = 0, phase = 0, weight = 0;
    };
    static constexpr double kNoiseWeight = 1.5;
    static constexpr double kLattice = 8;  // cells across [-1, 1]

    double lattice(std::int64_t i, std::int64_t j) const {
        return double(hash3(seed_, i, j) >> 11) * 0x1.0p-52 - 1;  // [-1, 1)
    }
    // Value noise: bilinear between lattice values with smoothstep weights.
    double noise(double x, double z) const {
        double u = (x + 1) / 2 * kLattice, v = (z + 1) / 2 * kLattice;
        double fu = std::floor(u), fv = std::floor(v);
        auto i = static_cast<std::int64_t>(fu), j = static_cast<std::int64_t>(fv);
        double s = u - fu, t = v - fv;
        s = s * s * (3 - 2 * s);
        t = t * t * (3 - 2 * t);
        double bottom = lattice(i, j) * (1 - s) + lattice(i + 1, j) * s;
        double top = lattice(i, j + 1) * (1 - s) + lattice(i + 1, j + 1) * s;
        return bottom * (1 - t) + top * t;
    }

    std::uint64_t seed_;
    Wave waves_[4];
};

}  // namespace

TriangleMesh make_terrain(int cells_x, int cells_z, std::uint64_t seed, Real height) {
    require(cells_x >= 1 && cells_z >= 1, "make_terrain: cells_x and cells_z must be >= 1, got " +
                                              std::to_string(cells_x) + " and " +
                                              std::to_string(cells_z));
    require_count(2.0 * cells_x * cells_z, "make_terrain");
    require(std::isfinite(double(height)) && height >= 0,
            "make_terrain: height must be a finite number >= 0");

    const std::size_t columns = std::size_t(cells_x) + 1, rows = std::size_t(cells_z) + 1;
    HeightField field(seed);
    std::vector<double> heights;
    heights.reserve(columns * rows);
    for (std::size_t k = 0; k < rows; ++k)
        for (std::size_t i = 0; i < columns; ++i)
            heights.push_back(double(height) *
                              field(-1 + 2 * double(i) / cells_x, -1 + 2 * double(k) / cells_z));
    return make_height_grid(columns, rows, heights);
}

// ---- triangle soup --------------------------------------------------------------------------

TriangleMesh make_triangle_soup(std::size_t count, std::uint64_t seed, Real size) {
    require_count(double(count), "make_triangle_soup");
    require_positive(double(size), "size", "make_triangle_soup");

    // Corners are uniform in a cube of side 1.5 * size around the triangle's centre (two random
    // points in a cube of side L are about 0.66 L apart), the whole triangle inside [-1, 1]^3.
    const double half = std::min(0.75 * double(size), 1.0);
    SplitMix64 random(seed);
    TriangleMesh mesh;
    mesh.vertices.reserve(3 * count);
    mesh.triangles.reserve(count);
    // One draw per statement: the order in which function arguments are evaluated is up to the
    // compiler (GCC and Clang differ), the order of statements is not.
    auto draw = [&random](double lo, double hi) {
        double x = random.between(lo, hi);
        double y = random.between(lo, hi);
        double z = random.between(lo, hi);
        return D3(x, y, z);
    };
    while (mesh.triangles.size() < count) {
        D3 center = draw(half - 1, 1 - half);
        D3 corner[3];
        for (D3& p : corner) p = center + draw(-half, half);
        // Redraw slivers: a tiny area compared with the size makes a useless test triangle.
        D3 n = glm::cross(corner[1] - corner[0], corner[2] - corner[0]);
        if (!(glm::dot(n, n) > 1e-6 * half * half * half * half)) continue;
        auto first = std::uint32_t(mesh.vertices.size());
        for (const D3& p : corner) mesh.vertices.push_back(to_real(p));
        mesh.triangles.push_back({first, first + 1, first + 2});
    }
    return mesh;
}

// ---- by name --------------------------------------------------------------------------------

const std::vector<std::string>& procedural_shapes() {
    static const std::vector<std::string> names(std::begin(kShapeNames), std::end(kShapeNames));
    return names;
}

ProceduralResolution procedural_resolution(std::string_view shape, std::size_t min_triangles) {
    std::size_t n = std::max<std::size_t>(min_triangles, 1);
    require(
        std::find(std::begin(kShapeNames), std::end(kShapeNames), shape) != std::end(kShapeNames),
        "unknown procedural mesh \"" + std::string(shape.substr(0, 40)) + "\"; use " +
            known_shapes());
    require(n <= kMaxProceduralTriangles, "a procedural " + std::string(shape) + " of " +
                                              std::to_string(min_triangles) +
                                              " triangles is more than the " +
                                              std::to_string(kMaxProceduralTriangles) + " allowed");
    ProceduralResolution r;
    if (shape == "icosphere") {
        std::size_t triangles = 20;
        while (triangles < n) {
            triangles *= 4;
            ++r.a;
        }
        r.triangles = triangles;
    } else if (shape == "torus") {
        // About twice as many rings as sides (the tube is thinner than the ring), then the fewest
        // rings that reach n.
        std::size_t sides = std::max<std::size_t>(3, ceil_sqrt(ceil_div(n, 4)));
        std::size_t rings = std::max<std::size_t>(3, ceil_div(n, 2 * sides));
        r.a = int(rings);
        r.b = int(sides);
        r.triangles = 2 * rings * sides;
    } else if (shape == "terrain") {
        // Square-ish cells: cells_z from the square root, then the fewest columns that reach n.
        std::size_t cells_z = std::max<std::size_t>(1, ceil_sqrt(ceil_div(n, 2)));
        std::size_t cells_x = ceil_div(n, 2 * cells_z);
        r.a = int(cells_x);
        r.b = int(cells_z);
        r.triangles = 2 * cells_x * cells_z;
    } else {
        r.a = int(n);
        r.triangles = n;
    }
    return r;
}

TriangleMesh make_procedural_mesh(std::string_view shape, std::size_t min_triangles,
                                  std::uint64_t seed) {
    ProceduralResolution r = procedural_resolution(shape, min_triangles);
    require(r.triangles <= kMaxProceduralTriangles,
            "a procedural " + std::string(shape) + " needs " + std::to_string(r.triangles) +
                " triangles to reach " + std::to_string(min_triangles) + ", more than the " +
                std::to_string(kMaxProceduralTriangles) + " allowed");
    if (shape == "icosphere") return make_icosphere(r.a);
    if (shape == "torus") return make_torus(r.a, r.b);
    if (shape == "terrain") return make_terrain(r.a, r.b, seed);
    return make_triangle_soup(std::size_t(r.a), seed);
}

}  // namespace rt
