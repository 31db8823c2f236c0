#include "testing/expect_near.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rt::testing {

std::string text(const Vec3& v) {
    std::ostringstream out;
    out << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return out.str();
}

void expect_vec_near(const Vec3& actual, const Vec3& expected, const std::string& what, Real tol,
                     std::source_location where) {
    const ::testing::ScopedTrace trace(where.file_name(), int(where.line()),
                                       "the check that failed");
    const std::string both = ": got " + text(actual) + ", expected " + text(expected);
    EXPECT_NEAR(actual.x, expected.x, tol) << what << ", x component" << both;
    EXPECT_NEAR(actual.y, expected.y, tol) << what << ", y component" << both;
    EXPECT_NEAR(actual.z, expected.z, tol) << what << ", z component" << both;
}

void expect_color_near(const Color& actual, const Color& expected, const std::string& what,
                       float tol, Scale scale, std::source_location where) {
    const ::testing::ScopedTrace trace(where.file_name(), int(where.line()),
                                       "the check that failed");
    const std::string both = ": got " + text(actual) + ", expected " + text(expected);
    auto bound = [&](float e) {
        return scale == Scale::Relative ? tol * std::max(1.0f, std::abs(e)) : tol;
    };
    EXPECT_NEAR(actual.r, expected.r, bound(expected.r)) << what << ", red" << both;
    EXPECT_NEAR(actual.g, expected.g, bound(expected.g)) << what << ", green" << both;
    EXPECT_NEAR(actual.b, expected.b, bound(expected.b)) << what << ", blue" << both;
}

}  // namespace rt::testing
