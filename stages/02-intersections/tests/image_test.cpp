// Stage 02 image tests: each scene of stages/02-intersections/scenes rendered with your code
// (in the scene's debug mode) and compared with reference_images/02-intersections/.
#include "testing/stage_test.h"

namespace rt {
namespace {

RT_TEST_SUITE(Image);

void check(const char* scene) { testing::expect_matches_reference("02-intersections", scene); }

TEST_F(Image, SpheresNormals) { check("spheres_normals"); }
TEST_F(Image, PlaneDepth) { check("plane_depth"); }
TEST_F(Image, TrianglesNormals) { check("triangles_normals"); }
TEST_F(Image, BoxesPrimitiveIds) { check("boxes_primitive_ids"); }
TEST_F(Image, MeshNormals) { check("mesh_normals"); }
TEST_F(Image, OrthographicMixed) { check("orthographic_mixed"); }

}  // namespace
}  // namespace rt
