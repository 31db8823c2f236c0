// Internal to the accuracy lab: the cases, their exact answers, and the measuring functions that
// live in measure.cpp. That file is compiled without CGAL's -frounding-math, like the renderer,
// so the timed methods are optimised as they would be in the ray tracer.
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "bench/accuracy.h"
#include "bench/methods.h"

namespace rt::bench::detail {

using V3f = glm::vec<3, float>;

// The spacing of T numbers at |x|.
template <typename T>
double ulp_at(double x) {
    const T r = std::abs(T(x));
    if (!std::isfinite(r)) return std::numeric_limits<double>::infinity();
    return double(std::nextafter(r, std::numeric_limits<T>::infinity())) - double(r);
}

// An exact t kept as an unevaluated double-double sum (enough to measure double ulps).
struct ExactT {
    double hi = 0, lo = 0;
    template <typename T>
    double ulps(T computed) const {
        const double err = std::abs((double(computed) - hi) - lo);
        return err / ulp_at<T>(hi);
    }
};

// ---------------------------------------------------------------------------------------------
// Cases.

struct TriangleCase {  // single triangle
    V3f o, d, a, b, c;
};
struct MeshData {
    std::vector<V3f> v;
    std::vector<std::array<int, 3>> tri;
};
struct MeshCase {
    V3f o, d;
    int mesh;
};
struct SphereCase {
    V3f o, d, center;
    float radius;
};

struct Scenario {
    ScenarioInfo info;
    std::vector<TriangleCase> tris;
    std::vector<MeshData> meshes;
    std::vector<MeshCase> rays;
    std::vector<SphereCase> spheres;
};

struct PairTruth {
    bool hit = false;
    int facing = 0;  // sign of n.d: -1 the ray enters (front face), +1 leaves, 0 parallel
    int region = 0;  // 0 interior, 1 edge, 2 vertex (when hit)
    ExactT t;
};

struct SphereTruthLite {
    bool hit = false;
    ExactT t;
};

struct TriTruthSet {
    std::vector<PairTruth> single;             // single-triangle scenarios
    std::vector<std::vector<PairTruth>> mesh;  // per ray, per triangle
    double ns = 0;
    long tests = 0;
};

// One mesh ray's verdict from the exact and the reported hits per triangle.
struct MeshVerdict {
    bool false_miss = false, false_hit = false, leak = false, double_hit = false;
};
MeshVerdict judge_mesh(const std::vector<PairTruth>& truth, const std::vector<char>& reported);

// The rows of every method in float and double for one scenario (timed if `timing`).
void triangle_rows(const Scenario& s, const TriTruthSet& truth, bool timing, std::vector<Row>& out);
void sphere_rows(const Scenario& s, const std::vector<SphereTruthLite>& truth, bool timing,
                 std::vector<Row>& out);
void rendering(const AccuracyConfig& config, AccuracyResults& results);

}  // namespace rt::bench::detail
