// Stage 01 tests: primary rays checked against closed forms.
// Run: ctest --test-dir build -L stage01 --output-on-failure
//   (or build/bin/stage01_tests --gtest_filter='Perspective.*')
#include <cmath>
#include <source_location>
#include <sstream>
#include <string>

#include "render/camera_ray.h"
#include "stage_api/stage01.h"
#include "testing/expect_near.h"
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

using rt::testing::expect_vec_near;

// Where to look when the y components are wrong everywhere: the image's y grows downwards.
constexpr const char* kFlipHint =
    " (y grows downwards: stages/01-camera-rays/README.md#from-a-pixel-to-the-image-plane)";

RT_TEST_SUITE(Perspective, "perspective-rays");

// The centre of the image (W/2, H/2) looks straight ahead along -w.
TEST_F(Perspective, CenterLooksAlongViewDirection) {
    const Camera cam = canonical(Projection::Perspective, 60);
    const Ray ray = perspective_ray(cam, Vec2(320, 240), ImageSize{640, 480});
    expect_vec_near(ray.origin, Vec3(0), "origin of the ray through the image centre (320, 240)");
    expect_vec_near(ray.direction, Vec3(0, 0, -1),
                    "direction through the image centre (320, 240), should be -w");
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
    const std::string corners = std::string(" of a 100x100 image, fov 90") + kFlipHint;
    expect_vec_near(perspective_ray(cam, Vec2(0, 0), size).direction, Vec3(-s, s, -s),
                    "top-left corner (0, 0)" + corners);
    expect_vec_near(perspective_ray(cam, Vec2(100, 0), size).direction, Vec3(s, s, -s),
                    "top-right corner (100, 0)" + corners);
    expect_vec_near(perspective_ray(cam, Vec2(0, 100), size).direction, Vec3(-s, -s, -s),
                    "bottom-left corner (0, 100)" + corners);
    expect_vec_near(perspective_ray(cam, Vec2(100, 100), size).direction, Vec3(s, -s, -s),
                    "bottom-right corner (100, 100)" + corners);
}

// The field of view is vertical: on a 2:1 image the horizontal extent is twice the vertical.
TEST_F(Perspective, AspectRatioWidensHorizontally) {
    const Camera cam = canonical(Projection::Perspective, 90);
    const ImageSize size{200, 100};
    const Ray right = perspective_ray(cam, Vec2(200, 50), size);  // middle of the right edge
    const Ray top = perspective_ray(cam, Vec2(100, 0), size);     // middle of the top edge
    EXPECT_NEAR(right.direction.x / -right.direction.z, 2, kTol)
        << "middle of the right edge (200, 50) of a 200x100 image, fov 90: x / -z should be the "
           "aspect ratio 2 times tan(45 deg) (the field of view is vertical)";
    EXPECT_NEAR(top.direction.y / -top.direction.z, 1, kTol)
        << "middle of the top edge (100, 0) of a 200x100 image, fov 90: y / -z should be "
           "tan(45 deg) = 1 (the field of view is in degrees and std::tan takes radians: "
           "convert with glm::radians)";
}

// Pixel (0, 0) has its centre at (0.5, 0.5): the renderer passes pixel centres, and y grows
// downwards, so the ray through pixel (0, 0)'s centre goes up and to the left, symmetric to
// the one through the last pixel's centre.
TEST_F(Perspective, PixelCentersAreSymmetric) {
    const Camera cam = canonical(Projection::Perspective, 50);
    const ImageSize size{4, 2};
    const Vec3 first = perspective_ray(cam, Vec2(0.5, 0.5), size).direction;
    const Vec3 last = perspective_ray(cam, Vec2(3.5, 1.5), size).direction;
    EXPECT_LT(first.x, 0) << "the centre (0.5, 0.5) of pixel (0, 0) is left of the image centre";
    EXPECT_GT(first.y, 0) << "the centre (0.5, 0.5) of pixel (0, 0) is above the image centre"
                          << kFlipHint;
    expect_vec_near(
        first, Vec3(-last.x, -last.y, last.z),
        "pixel (0, 0) at (0.5, 0.5) mirrored against the last pixel (3, 1) at (3.5, 1.5) of "
        "a 4x2 image (adding another + 0.5 breaks the symmetry)");
    // With tan(25 deg) = h, the pixel centre at y = 0.5 of 2 rows sits at half the height.
    const Real h = std::tan(glm::radians(Real(25)));
    EXPECT_NEAR(first.y / -first.z, h / 2, kTol)
        << "pixel (0, 0) of a 4x2 image, fov 50: its centre is half way up, y / -z = tan(25 deg) / "
           "2";
    EXPECT_NEAR(first.x / -first.z, -h * 2 * Real(0.75), kTol)
        << "pixel (0, 0) of a 4x2 image, fov 50: its centre is 3/4 of the way left, "
           "x / -z = -aspect 2 * tan(25 deg) * 0.75";
}

// The camera frame is respected: the same image point in a rotated camera gives the rotated ray.
TEST_F(Perspective, FollowsCameraFrame) {
    const Camera cam = make_look_at_camera(Projection::Perspective, Vec3(1, 2, 3),
                                           Vec3(1, 2, 3) + Vec3(1, 0, 0), Vec3(0, 1, 0), 90, 2);
    const Ray center = perspective_ray(cam, Vec2(50, 50), ImageSize{100, 100});
    expect_vec_near(center.origin, Vec3(1, 2, 3),
                    "origin of the centre ray, camera at (1, 2, 3) looking along +x: camera.eye");
    expect_vec_near(center.direction, Vec3(1, 0, 0),
                    "direction of the centre ray, camera looking along +x (-camera.w)");
    // Looking along +x with y up, the camera's right (u) is +z.
    const Ray right_edge = perspective_ray(cam, Vec2(100, 50), ImageSize{100, 100});
    const Real s = Real(1) / std::sqrt(Real(2));
    expect_vec_near(right_edge.direction, Vec3(s, 0, s),
                    "middle of the right edge (100, 50), camera looking along +x: right is "
                    "camera.u = +z");
}

RT_TEST_SUITE(Orthographic, "orthographic-rays");

// All orthographic rays are parallel to the view direction.
TEST_F(Orthographic, DirectionsAreTheViewDirection) {
    const Camera cam =
        make_look_at_camera(Projection::Orthographic, Vec3(0, 0, 5), Vec3(0), Vec3(0, 1, 0), 45, 4);
    for (Real x : {Real(0.5), Real(63.5), Real(127.5)})
        for (Real y : {Real(0.5), Real(31.5)}) {
            const Ray ray = orthographic_ray(cam, Vec2(x, y), ImageSize{128, 64});
            expect_vec_near(ray.direction, Vec3(0, 0, -1),
                            "orthographic direction at image point (" + std::to_string(x) + ", " +
                                std::to_string(y) + "), should be -camera.w");
        }
}

// Origins span view_height vertically and view_height * aspect horizontally, centred on the eye.
TEST_F(Orthographic, OriginsSpanTheViewRectangle) {
    const Camera cam =
        make_look_at_camera(Projection::Orthographic, Vec3(0, 0, 5), Vec3(0), Vec3(0, 1, 0), 45, 4);
    const ImageSize size{200, 100};  // 2:1, so the rectangle is 8 x 4
    const std::string rect = std::string(" of a 200x100 image, 8 x 4 view rectangle") + kFlipHint;
    expect_vec_near(orthographic_ray(cam, Vec2(0, 0), size).origin, Vec3(-4, 2, 5),
                    "origin at the top-left corner (0, 0)" + rect);
    expect_vec_near(orthographic_ray(cam, Vec2(200, 100), size).origin, Vec3(4, -2, 5),
                    "origin at the bottom-right corner (200, 100)" + rect);
    expect_vec_near(orthographic_ray(cam, Vec2(100, 50), size).origin, Vec3(0, 0, 5),
                    "origin at the image centre (100, 50): camera.eye");
    // Pixel centre of the top-left pixel: half a pixel (0.04 world units) in from each edge.
    expect_vec_near(orthographic_ray(cam, Vec2(0.5, 0.5), size).origin, Vec3(-3.98, 1.98, 5),
                    "origin at the centre (0.5, 0.5) of the top-left pixel" + rect);
}

// The orthographic camera ignores the field of view.
TEST_F(Orthographic, IgnoresFieldOfView) {
    Camera a = canonical(Projection::Orthographic, 30, 3);
    Camera b = canonical(Projection::Orthographic, 120, 3);
    const Ray ra = orthographic_ray(a, Vec2(10, 20), ImageSize{64, 48});
    const Ray rb = orthographic_ray(b, Vec2(10, 20), ImageSize{64, 48});
    expect_vec_near(ra.origin, rb.origin,
                    "origin at image point (10, 20) with fov 120 against fov 30 (orthographic "
                    "ignores the field of view)");
    expect_vec_near(ra.direction, rb.direction,
                    "direction at image point (10, 20) with fov 120 against fov 30 (orthographic "
                    "ignores the field of view)");
}

RT_TEST_SUITE(CameraRay, "from-a-pixel-to-the-image-plane");

// The framework's camera_ray dispatches on the projection to your two functions.
TEST_F(CameraRay, DispatchesOnProjection) {
    const ImageSize size{64, 64};
    const Camera persp = canonical(Projection::Perspective, 90);
    const Camera ortho = canonical(Projection::Orthographic, 90, 2);
    expect_vec_near(camera_ray(persp, Vec2(0, 32), size).direction, glm::normalize(Vec3(-1, 0, -1)),
                    "camera_ray with a perspective camera, left edge (0, 32): perspective_ray");
    expect_vec_near(camera_ray(ortho, Vec2(0, 32), size).origin, Vec3(-1, 0, 0),
                    "camera_ray with an orthographic camera, left edge (0, 32): orthographic_ray");
}

}  // namespace
}  // namespace rt
