// The accuracy lab's claims, checked on fixed seeds (classification only; no timing, no
// rendering). Set RT_ACCURACY_NAIVE=1 to swap each method under test for its naive counterpart
// (watertight -> Cramer, RTG sphere -> textbook, robust offset -> fixed tmin): every test but
// the contraction probe must then fail, which shows that it can.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <string>

#include "bench/accuracy.h"
#include "bench/methods.h"
#include "core/source_dir.h"
#include "core/text_file.h"
#include "geometry/offset.h"

namespace rt::bench {
namespace {

bool naive() {
    const char* e = std::getenv("RT_ACCURACY_NAIVE");
    return e && *e && std::string(e) != "0";
}

AccuracyResults run(std::uint64_t seed, int cases, bool self, const std::string& family = "") {
    AccuracyConfig c;
    c.seed = seed;
    c.cases = cases;
    c.timing = false;
    c.rendering = false;
    c.textures = false;
    c.self_intersection = self;
    c.family = family;
    return run_accuracy(c);
}

constexpr std::uint64_t kSeed = 1;
constexpr int kCases = 10000;

// docs/accuracy.md's counts (RT_ACCURACY_REPORT names another file, to check by hand that a
// wrong count fails). Report.CountsMatchAFreshRun checks them against a fresh run.
ReportCounts published_counts() {
    const char* other = std::getenv("RT_ACCURACY_REPORT");
    const std::filesystem::path file =
        other && *other ? std::filesystem::path(other) : rt::source_dir() / "docs/accuracy.md";
    return parse_report(read_text_file(file, 16u << 20, [&](const FileProblem&) {
        throw std::runtime_error(file.string() +
                                 " cannot be read; regenerate it (its first lines)");
    }));
}

// Watertight promises that no ray slips between faces that share an edge or a vertex; its 2D
// test is exact for the rounded, sheared vertices, not for the input triangle. So: zero leaks on
// every scenario and zero false misses wherever rounding cannot move an edge across the ray
// (every scenario in double; in float every one but single slivers and grazing rays, where one
// float rounding of a projected vertex exceeds the ray's distance to the edge: the report shows
// those counts, about equal to Cramer's). Checked on the published counts, which
// Report.CountsMatchAFreshRun recomputes: the same 10,000 rays per scenario, classified once
// per CI run instead of twice (half a minute of CPU each).
TEST(Watertight, NoLeaksAndNoFalseMissesOnEveryScenario) {
    const std::string method = naive() ? "Cramer" : "watertight";
    const ReportCounts published = published_counts();
    ASSERT_FALSE(published.rows.empty()) << "docs/accuracy.md is missing or has no table";
    EXPECT_GE(published.cases, kCases);
    AccuracyResults r;
    r.rows = published.rows;
    int checked = 0;
    for (const ScenarioInfo& s : scenarios()) {
        if (s.family != "triangle") continue;
        for (const std::string precision : {"float", "double"}) {
            const Row* row = find(r, s.key, method, precision);
            ASSERT_NE(row, nullptr);
            const std::string what = s.key + " " + method + " " + precision;
            EXPECT_EQ(row->counts.leak, 0) << what;
            const bool ill_conditioned = s.key == "sliver" || s.key == "grazing";
            if (precision == "double" || !ill_conditioned) {
                EXPECT_EQ(row->counts.false_miss, 0) << what;
            }
            ++checked;
        }
    }
    EXPECT_EQ(checked, 18);
}

TEST(Sphere, StableFormHasNoFalseHitsOnFarSpheres) {
    const std::string method = naive() ? "textbook" : "RTG ch. 7";
    const AccuracyResults r = run(kSeed, kCases, false, "sphere");
    for (const char* precision : {"float", "double"}) {
        const Row* row = find(r, "far-small", method, precision);
        ASSERT_NE(row, nullptr);
        EXPECT_EQ(row->counts.false_hit, 0) << method << " " << precision;
        EXPECT_GT(row->counts.cases, 1000);
    }
}

TEST(Offset, RobustOffsetNeverSelfHitsAndKeepsCloseOccluders) {
    const std::string strategy = naive() ? "fixed tmin" : "robust offset";
    const AccuracyResults r = run(kSeed, kCases, true, "none");  // self-intersection only
    int checked = 0;
    for (const SelfRow& row : r.self) {
        if (row.strategy != strategy) continue;
        EXPECT_GT(row.rays, 1000);
        EXPECT_EQ(row.self_hits, 0) << strategy << " " << row.precision << " scale " << row.scale;
        EXPECT_EQ(row.missed_gap_1e2, 0)
            << strategy << " " << row.precision << " scale " << row.scale;
        ++checked;
    }
    EXPECT_EQ(checked, 6);  // scales 1, 1e2, 1e4 in float and double
}

TEST(Offset, BenchCopyMatchesTheFramework) {
    // The bench runs pbrt's OffsetRayOrigin on float and double (bench/methods.h); the renderer
    // uses framework/geometry/offset.h on rt::Real. Same inputs, same bits.
    std::mt19937_64 rng(7);
    auto u = [&](double lo, double hi) {
        return Real(lo + (hi - lo) * double(rng() >> 11) * 0x1p-53);
    };
    EXPECT_EQ(gamma_bound<Real>(7), rt::gamma_bound(7));
    for (int i = 0; i < 1000; ++i) {
        const double scale = std::pow(10.0, double(i % 5));
        const Vec3 p(u(-scale, scale), u(-scale, scale), u(-scale, scale));
        const Vec3 err = glm::abs(p) * gamma_bound<Real>(7);
        const Vec3 n = glm::normalize(Vec3(u(-1, 1), u(-1, 1), u(-1, 1)));
        const Vec3 d(u(-1, 1), u(-1, 1), u(-1, 1));
        EXPECT_EQ(offset_ray_origin<Real>(p, err, n, d), rt::offset_ray_origin(p, err, n, d));
    }
}

TEST(Build, ContractionIsOff) {
    // Exact a*b = 1 - 2^-60 rounds to 1 in double, so two roundings give 0; a fused
    // multiply-add would give -2^-60. multiply_add lives in another file (bench/fma_probe.cpp).
    // To see this fail, compile that file with -ffp-contract=fast -mfma (x86-64 without -mfma
    // has no FMA instruction to contract to) and relink this test.
    const double a = 1 + std::ldexp(1.0, -30), b = 1 - std::ldexp(1.0, -30);
    EXPECT_EQ(std::fma(a, b, -1.0), -std::ldexp(1.0, -60));  // the case does tell them apart
    EXPECT_EQ(multiply_add(a, b, -1.0), 0.0);
    const float af = 1 + std::ldexp(1.0f, -13), bf = 1 - std::ldexp(1.0f, -13);
    EXPECT_EQ(std::fma(af, bf, -1.0f), -std::ldexp(1.0f, -26));
    EXPECT_EQ(multiply_add(af, bf, -1.0f), 0.0f);
}

TEST(Report, CountsMatchAFreshRun) {
    // docs/accuracy.md stores its seed and case count and every classification count; a fresh
    // run with the same seed must reproduce them (times differ from run to run and are ignored).
    // RT_ACCURACY_REPORT names another file (to check by hand that a wrong count fails).
    const ReportCounts report = published_counts();
    ASSERT_FALSE(report.rows.empty())
        << "docs/accuracy.md is missing or has no table; regenerate it (see its first lines)";
    const AccuracyResults fresh = run(report.seed, report.cases, true);
    ASSERT_EQ(report.rows.size(), fresh.rows.size());
    for (std::size_t i = 0; i < fresh.rows.size(); ++i) {
        const Row& a = report.rows[i];
        const Row& b = fresh.rows[i];
        const std::string what = b.scenario + " " + b.method + " " + b.precision;
        EXPECT_EQ(a.scenario + " " + a.method + " " + a.precision, what);
        EXPECT_EQ(a.counts.cases, b.counts.cases) << what;
        EXPECT_EQ(a.counts.false_miss, b.counts.false_miss) << what;
        EXPECT_EQ(a.counts.false_hit, b.counts.false_hit) << what;
        EXPECT_EQ(a.counts.leak, b.counts.leak) << what;
        EXPECT_EQ(a.counts.double_hit, b.counts.double_hit) << what;
    }
    ASSERT_EQ(report.self.size(), fresh.self.size());
    for (std::size_t i = 0; i < fresh.self.size(); ++i) {
        const SelfRow& a = report.self[i];
        const SelfRow& b = fresh.self[i];
        const std::string what = b.strategy + " " + b.precision + " " + std::to_string(b.scale);
        EXPECT_EQ(a.rays, b.rays) << what;
        EXPECT_EQ(a.self_hits, b.self_hits) << what;
        EXPECT_EQ(a.occluder_rays, b.occluder_rays) << what;
        EXPECT_EQ(a.missed_gap_1e2, b.missed_gap_1e2) << what;
        EXPECT_EQ(a.missed_gap_1e4, b.missed_gap_1e4) << what;
    }
}

}  // namespace
}  // namespace rt::bench
