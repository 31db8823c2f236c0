// The framework's reference ray-triangle test: "Watertight Ray/Triangle Intersection",
// Woop, Benthin and Wald, JCGT 2(1), 2013. It never lets a ray slip between two triangles that
// share an edge or a vertex, whatever the rounding. Students write Cramer's rule in stage 02;
// tests compare both against exact arithmetic.
#pragma once

#include "core/hit.h"

namespace rt {

// Same contract as intersect_triangle in framework/stage_api/stage02.h (uv = barycentrics of b, c).
// Backface hits are reported (no culling). Edges and vertices count as inside.
bool intersect_triangle_watertight(const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c,
                                   Interval t_range, Hit& hit);

}  // namespace rt
