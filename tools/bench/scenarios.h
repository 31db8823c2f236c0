// The accuracy lab's cases from a seed: the scenarios of scenarios(), and the random helpers that
// the self-intersection experiment (accuracy.cpp) draws its rays with.
#pragma once

#include <cstdint>
#include <vector>

#include "bench/cases.h"
#include "testing/exact_reference.h"

namespace rt::bench::detail {

using V3d = glm::vec<3, double>;

// Every scenario of scenarios(), `n` cases each, each scenario its own stream of `seed`.
std::vector<Scenario> make_scenarios(std::uint64_t seed, int n);

V3d rvec(exact::Rng& rng, double lo, double hi);                    // uniform in [lo, hi)^3
V3d runit(exact::Rng& rng);                                         // a random unit vector
double log_uniform(exact::Rng& rng, double lo_exp, double hi_exp);  // 10^uniform(lo, hi)
// A random ray aimed at a point near (often inside) the triangle.
TriangleCase towards(exact::Rng& rng, const V3d& a, const V3d& b, const V3d& c, const V3d& origin);

}  // namespace rt::bench::detail
