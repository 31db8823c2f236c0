// Statistical checks for stage 10's tests (as Nori's warptest and its t-tests): a chi-square
// goodness-of-fit test of samples against expected bin counts, and a Student t-test of a Monte
// Carlo mean against a known value. Seeds are fixed, so each test gives the same verdict every
// run; the false-failure rates below are the chance that a correct implementation fails at a
// random seed.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <pcg_random.hpp>
#include <string>
#include <vector>

#include "core/real.h"

namespace rt::stats {

// Shared by the tests: pi, and the samples of one Monte Carlo estimate or histogram.
inline constexpr double kPi = 3.14159265358979323846;
inline constexpr int kSamples = 100000;

// Significance of each chi-square test: a correct sampler fails one in 1000 seeds.
inline constexpr double kChiSquareAlpha = 1e-3;
// |t| beyond this fails a mean: two-sided false-failure rate 1e-4 for a normal mean.
inline constexpr double kMaxT = 3.9;

// Uniform numbers in [0, 1) from a fixed seed (independent of the renderer's streams).
class Uniform {
  public:
    explicit Uniform(std::uint64_t seed) : rng_(seed, 54u) {}
    Real next() { return Real(rng_() >> 8) * Real(1.0 / 16777216.0); }
    Vec2 next2() {
        const Real a = next();
        return Vec2(a, next());
    }

  private:
    pcg32 rng_;
};

// Q(a, x), the regularised upper incomplete gamma function (Numerical Recipes 6.2).
inline double gamma_q(double a, double x) {
    if (x <= 0) return 1;
    const double log_prefix = -x + a * std::log(x) - std::lgamma(a);
    if (x < a + 1) {  // series for P
        double sum = 1 / a, term = sum;
        for (int n = 1; n < 1000; ++n) {
            term *= x / (a + n);
            sum += term;
            if (std::abs(term) < std::abs(sum) * 1e-15) break;
        }
        return 1 - sum * std::exp(log_prefix);
    }
    double b = x + 1 - a, c = 1e300, d = 1 / b, h = d;  // continued fraction for Q (Lentz)
    for (int i = 1; i < 1000; ++i) {
        const double an = -i * (i - a);
        b += 2;
        d = an * d + b;
        if (std::abs(d) < 1e-300) d = 1e-300;
        c = b + an / c;
        if (std::abs(c) < 1e-300) c = 1e-300;
        d = 1 / d;
        const double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1) < 1e-15) break;
    }
    return std::exp(log_prefix) * h;
}

// Pearson's test of `observed` counts against `expected` counts (same bins). Bins expected to
// hold fewer than 5 samples are pooled, as usual. A sample in a bin of expected count 0 fails
// at once. Adds a failure naming `what` when the p-value is below kChiSquareAlpha.
inline void expect_chi_square(const std::vector<double>& observed,
                              const std::vector<double>& expected, const std::string& what) {
    double chi2 = 0, pooled_observed = 0, pooled_expected = 0;
    int bins = 0;
    for (std::size_t i = 0; i < observed.size(); ++i) {
        if (expected[i] <= 0) {
            EXPECT_EQ(observed[i], 0) << what << ": " << observed[i]
                                      << " samples fell where the density is 0 (bin " << i << ")";
            continue;
        }
        if (expected[i] < 5) {
            pooled_observed += observed[i];
            pooled_expected += expected[i];
            continue;
        }
        chi2 += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
        ++bins;
    }
    if (pooled_expected > 0) {
        chi2 += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) /
                pooled_expected;
        ++bins;
    }
    ASSERT_GT(bins, 1) << what;
    const double p = gamma_q((bins - 1) / 2.0, chi2 / 2.0);
    EXPECT_GE(p, kChiSquareAlpha) << what
                                  << ": the samples do not follow the density (chi^2 = " << chi2
                                  << " over " << bins - 1 << " degrees of freedom, p = " << p
                                  << ")";
}

// Two samples of the same distribution? Counts of two equally large samples in the same bins
// (the two-sample form of Pearson's test); bins with fewer than 10 in both are pooled.
inline void expect_same_distribution(const std::vector<double>& a, const std::vector<double>& b,
                                     const std::string& what) {
    double chi2 = 0, pool_a = 0, pool_b = 0;
    int bins = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i] + b[i] < 10) {
            pool_a += a[i];
            pool_b += b[i];
            continue;
        }
        chi2 += (a[i] - b[i]) * (a[i] - b[i]) / (a[i] + b[i]);
        ++bins;
    }
    if (pool_a + pool_b > 0) {
        chi2 += (pool_a - pool_b) * (pool_a - pool_b) / (pool_a + pool_b);
        ++bins;
    }
    ASSERT_GT(bins, 1) << what;
    const double p = gamma_q((bins - 1) / 2.0, chi2 / 2.0);
    EXPECT_GE(p, kChiSquareAlpha) << what << ": the samples do not follow the reference "
                                  << "distribution (chi^2 = " << chi2 << " over " << bins - 1
                                  << " degrees of freedom, p = " << p << ")";
}

// Mean and standard error of a list of values.
struct Estimate {
    double mean = 0, standard_error = 0;
};

inline Estimate estimate(const std::vector<double>& values) {
    double sum = 0;
    for (double v : values) sum += v;
    const double mean = sum / double(values.size());
    double squares = 0;
    for (double v : values) squares += (v - mean) * (v - mean);
    const double variance = squares / double(values.size() - 1);
    return {mean, std::sqrt(variance / double(values.size()))};
}

// A t-test of the mean of `values` against `reference`: fails when |mean - reference| exceeds
// kMaxT standard errors (plus a relative 1e-4 for rounding, so a zero-variance estimator is
// compared with that).
inline void expect_mean(const std::vector<double>& values, double reference,
                        const std::string& what) {
    const Estimate e = estimate(values);
    const double allowed = kMaxT * e.standard_error + 1e-4 * std::max(1.0, std::abs(reference));
    EXPECT_LE(std::abs(e.mean - reference), allowed)
        << what << ": the mean of " << values.size() << " samples is " << e.mean
        << " (standard error " << e.standard_error << "), expected " << reference
        << "; t = " << (e.standard_error > 0 ? (e.mean - reference) / e.standard_error : 0.0);
}

}  // namespace rt::stats
