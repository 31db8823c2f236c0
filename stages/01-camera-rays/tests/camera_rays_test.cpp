// Stage 01 tests: primary rays checked against closed forms.
// Run: ctest --test-dir build -L stage01   (or build/bin/stage01_tests --gtest_filter='Perspective.*')
#include <cmath>

#include "student/stage01.h"
#include "testing/stage_test.h"

namespace rt {
namespace {

// A tolerance a few float ulps wide around 1: the arithmetic here is a handful of operations.
constexpr Real kTol = Real(1e-5);

// Canonical camera: at the origin, looking down -z, y up.
Camera canonical(Projection projection, Real fov = 90, Real view_height = 2) {
    return make_look_at_camera(projection, Vec3(0), Vec3(0, 0, -1), Vec3(0, 1, 0), fov,
                               view_height);
}

void expect_near(const Vec3& actual, const Vec3& expected, Real tol = kTol) {
    EXPECT_NEAR(actual.x, expected.x, tol) << "x component";
    EXPECT_NEAR(actual.y, expected.y, tol) << "y component";
    EXPECT_NEAR(actual.z, expected.z, tol) << "z component";
}

RT_TEST_SUITE(Perspective);

// The centre of the image (W/2, H/2) looks straight ahead along -w.
TEST_F(Perspective, CentreLooksAlongViewDirection) {
    const Camera cam = canonical(Projection::Perspective, 60);
    const Ray ray = perspective_ray(cam, Vec2(320, 240), ImageSize{640, 480});
    expect_near(ray.origin, Vec3(0));
    expect_near(ray.direction, Vec3(0, 0, -1));
}

// Directions are unit length everywhere, so t measures distance.
TEST_F(Perspective, DirectionsAreUnitLength) {
    const Camera cam = canonical(Projection::Perspective, 70);
    for (Real x : {Real(0), Real(13.5), Real(99.25), Real(200)})
        for (Real y : {Real(0), Real(50.5), Real(100)}) {
            const Ray ray = perspective_ray(cam, Vec2(x, y), ImageSize{200, 100});
            EXPECT_NEAR(glm::length(ray.direction), 1, kTol) << "at image point " << x << "," << y;
        }
}

// fov 90 on a square image: the top-left corner of the image is the direction (-1, 1, -1).
TEST_F(Perspective, CornersFollowFieldOfView) {
    const Camera cam = canonical(Projection::Perspective, 90);
    const ImageSize size{100, 100};
    const Real s = Real(1) / std::sqrt(Real(3));
    expect_near(perspective_ray(cam, Vec2(0, 0), size).direction, Vec3(-s, s, -s));
    expect_near(perspective_ray(cam, Vec2(100, 0), size).direction, Vec3(s, s, -s));
    expect_near(perspective_ray(cam, Vec2(0, 100), size).direction, Vec3(-s, -s, -s));
    expect_near(perspective_ray(cam, Vec2(100, 100), size).direction, Vec3(s, -s, -s));
}

// The field of view is vertical: on a 2:1 image the horizontal extent is twice the vertical.
TEST_F(Perspective, AspectRatioWidensHorizontally) {
    const Camera cam = canonical(Projection::Perspective, 90);
    const ImageSize size{200, 100};
    const Ray right = perspective_ray(cam, Vec2(200, 50), size);  // middle of the right edge
    const Ray top = perspective_ray(cam, Vec2(100, 0), size);     // middle of the top edge
    EXPECT_NEAR(right.direction.x / -right.direction.z, 2, kTol);
    EXPECT_NEAR(top.direction.y / -top.direction.z, 1, kTol);
}

// Pixel (0, 0) has its centre at (0.5, 0.5): the renderer passes pixel centres, and y grows
// downwards, so the ray through pixel (0, 0)'s centre goes up and to the left, symmetric to
// the one through the last pixel's centre.
TEST_F(Perspective, PixelCentresAreSymmetric) {
    const Camera cam = canonical(Projection::Perspective, 50);
    const ImageSize size{4, 2};
    const Vec3 first = perspective_ray(cam, Vec2(0.5, 0.5), size).direction;
    const Vec3 last = perspective_ray(cam, Vec2(3.5, 1.5), size).direction;
    EXPECT_LT(first.x, 0);
    EXPECT_GT(first.y, 0);
    expect_near(first, Vec3(-last.x, -last.y, last.z));
    // With tan(25 deg) = h, the pixel centre at y = 0.5 of 2 rows sits at half the height.
    const Real h = std::tan(glm::radians(Real(25)));
    EXPECT_NEAR(first.y / -first.z, h / 2, kTol);
    EXPECT_NEAR(first.x / -first.z, -h * 2 * Real(0.75), kTol);
}

// The camera frame is respected: the same image point in a rotated camera gives the rotated ray.
TEST_F(Perspective, FollowsCameraFrame) {
    const Camera cam = make_look_at_camera(Projection::Perspective, Vec3(1, 2, 3),
                                           Vec3(1, 2, 3) + Vec3(1, 0, 0), Vec3(0, 1, 0), 90, 2);
    const Ray centre = perspective_ray(cam, Vec2(50, 50), ImageSize{100, 100});
    expect_near(centre.origin, Vec3(1, 2, 3));
    expect_near(centre.direction, Vec3(1, 0, 0));
    // Looking along +x with y up, the camera's right (u) is +z.
    const Ray right_edge = perspective_ray(cam, Vec2(100, 50), ImageSize{100, 100});
    const Real s = Real(1) / std::sqrt(Real(2));
    expect_near(right_edge.direction, Vec3(s, 0, s));
}

RT_TEST_SUITE(Orthographic);

// All orthographic rays are parallel to the view direction.
TEST_F(Orthographic, DirectionsAreTheViewDirection) {
    const Camera cam = make_look_at_camera(Projection::Orthographic, Vec3(0, 0, 5), Vec3(0),
                                           Vec3(0, 1, 0), 45, 4);
    for (Real x : {Real(0.5), Real(63.5), Real(127.5)})
        for (Real y : {Real(0.5), Real(31.5)}) {
            const Ray ray = orthographic_ray(cam, Vec2(x, y), ImageSize{128, 64});
            expect_near(ray.direction, Vec3(0, 0, -1));
        }
}

// Origins span view_height vertically and view_height * aspect horizontally, centred on the eye.
TEST_F(Orthographic, OriginsSpanTheViewRectangle) {
    const Camera cam = make_look_at_camera(Projection::Orthographic, Vec3(0, 0, 5), Vec3(0),
                                           Vec3(0, 1, 0), 45, 4);
    const ImageSize size{200, 100};  // 2:1, so the rectangle is 8 x 4
    expect_near(orthographic_ray(cam, Vec2(0, 0), size).origin, Vec3(-4, 2, 5));
    expect_near(orthographic_ray(cam, Vec2(200, 100), size).origin, Vec3(4, -2, 5));
    expect_near(orthographic_ray(cam, Vec2(100, 50), size).origin, Vec3(0, 0, 5));
    // Pixel centre of the top-left pixel: half a pixel (0.04 world units) in from each edge.
    expect_near(orthographic_ray(cam, Vec2(0.5, 0.5), size).origin, Vec3(-3.98, 1.98, 5));
}

// The orthographic camera ignores the field of view.
TEST_F(Orthographic, IgnoresFieldOfView) {
    Camera a = canonical(Projection::Orthographic, 30, 3);
    Camera b = canonical(Projection::Orthographic, 120, 3);
    const Ray ra = orthographic_ray(a, Vec2(10, 20), ImageSize{64, 48});
    const Ray rb = orthographic_ray(b, Vec2(10, 20), ImageSize{64, 48});
    expect_near(ra.origin, rb.origin);
    expect_near(ra.direction, rb.direction);
}

RT_TEST_SUITE(CameraRay);

// The framework's camera_ray dispatches on the projection to your two functions.
TEST_F(CameraRay, DispatchesOnProjection) {
    const ImageSize size{64, 64};
    const Camera persp = canonical(Projection::Perspective, 90);
    const Camera ortho = canonical(Projection::Orthographic, 90, 2);
    expect_near(camera_ray(persp, Vec2(0, 32), size).direction,
                glm::normalize(Vec3(-1, 0, -1)));
    expect_near(camera_ray(ortho, Vec2(0, 32), size).origin, Vec3(-1, 0, 0));
}

}  // namespace
}  // namespace rt
