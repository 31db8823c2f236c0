// The leaderboard's traversal cost (docs/grading.md, "The leaderboard"): how much work a tree
// makes a traversal do, the same on every machine. Two `rt` subcommands, run by rt-grade:
//   rt bvh-dump SCENE -o TREE     the student's renderer writes the tree its build_bvh made
//   rt bvh-cost SCENE [--tree TREE]
//                                 the reference renderer checks TREE against the primitives it
//                                 prepared itself (validate_bvh) and traces every pixel's primary
//                                 ray through it with its own traversal, counting node visits and
//                                 primitive tests; without --tree, through its own tree
// The count is made by the reference's code on the student's tree as data, so no student code
// runs where it is counted: a tree that is not a valid BVH of the scene is refused, not costed.
#pragma once

#include <string>

namespace rt {

// The figure a leaderboard ranks by: node visits per ray plus kPrimitiveTestWeight times
// primitive tests per ray (a box test is far cheaper than a triangle test).
inline constexpr double kPrimitiveTestWeight = 10;

int run_bvh_dump(const std::string& scene_file, const std::string& tree_file);
// `width` and `height` > 0 trace that many rays instead of the scene's image size (tests).
int run_bvh_cost(const std::string& scene_file, const std::string& tree_file, int width = 0,
                 int height = 0);

}  // namespace rt
