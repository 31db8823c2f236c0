// Stage 09, BVH traversal: stage 06's queries (stages/06-bvh/bvh.cpp) in GLSL, over the nodes
// the CPU built (bvh_nodes_at(i), bvh_primitives_at(k): framework/accel/bvh.h). GLSL has no recursion
// and no pointers: a node is its index, and the nodes still to visit wait on a fixed-size stack
// (the builder never makes a tree deeper than kBvhMaxDepth, which the framework's prelude
// defines as accel/bvh.h does). Planes stay outside the tree.
// Handout: stages/09-gpu/README.md#bvh-traversal.

// Ray-box slab test for a node, as stage 06's intersect_node: true when the segment t_range
// meets the box, t_entry where it enters (clamped to t_range.min). Never miss a box a primitive
// inside it is hit in: widen the exit distance by the rounding bound, as stage 06 does.
bool intersect_node(BvhNode node, Ray ray, vec3 inv_direction, Interval t_range,
                    out float t_entry) {
    // BEGIN SOLUTION
    const float eps = 5.9604644775390625e-8;  // 2^-24
    const float growth = 1.0 + 2.0 * (3.0 * eps) / (1.0 - 3.0 * eps);
    float t0 = t_range.min;
    float t1 = t_range.max;
    for (int axis = 0; axis < 3; ++axis) {
        // A positive direction meets the slab's min plane first, a negative one its max plane.
        const bool negative = inv_direction[axis] < 0.0;
        const float near_plane = negative ? node.max[axis] : node.min[axis];
        const float far_plane = negative ? node.min[axis] : node.max[axis];
        const float near = (near_plane - ray.origin[axis]) * inv_direction[axis];
        const float far = (far_plane - ray.origin[axis]) * inv_direction[axis] * growth;
        // Written so that a NaN (0 * inf: the origin on the plane) leaves the interval as it is.
        t0 = near > t0 ? near : t0;
        t1 = far < t1 ? far : t1;
    }
    t_entry = t0;
    return t0 <= t1;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#bvh-traversal
    // t_entry = 0.0;
    // return false;
    // END SOLUTION
}

// BEGIN SOLUTION
// STUB
// // Helper functions of your own may go here.
// END SOLUTION

// The nearest hit in t_range (planes one by one, then the tree): nearer child first, skipping
// a node that starts beyond the nearest hit so far. intersect_primitive (given) tests one
// primitive by its global id and fills hit.primitive and hit.material. Add each node whose box
// you test to bvh_nodes_visited (stage 06's stats->nodes_visited; the bvh_visits view).
bool bvh_intersect_nearest(Ray ray, Interval t_range, inout Hit hit) {
    // BEGIN SOLUTION
    bool found = false;
    for (int i = 0; i < primitive_counts.y; ++i) {
        if (intersect_primitive(primitive_id(kPlane, i), ray, t_range, hit)) {
            found = true;
            t_range.max = hit.t;  // what follows must be nearer
        }
    }
    const vec3 inv_direction = 1.0 / ray.direction;
    // The nodes still to visit and where the ray enters them: the far children waiting, and the
    // near one about to be taken.
    uint stack_node[kBvhMaxDepth];
    float stack_t[kBvhMaxDepth];
    int top = 0;
    float t_root;
    bvh_nodes_visited += 1u;
    if (intersect_node(bvh_nodes_at(0), ray, inv_direction, t_range, t_root)) {
        stack_node[0] = 0u;
        stack_t[0] = t_root;
        top = 1;
    }
    while (top > 0) {
        --top;
        if (stack_t[top] > t_range.max) continue;  // a nearer hit was found after the push
        const BvhNode node = bvh_nodes_at(stack_node[top]);
        if (node.count > 0u) {
            for (uint k = node.first; k < node.first + node.count; ++k) {
                if (intersect_primitive(int(bvh_primitives_at(k)), ray, t_range, hit)) {
                    found = true;
                    t_range.max = hit.t;
                }
            }
            continue;
        }
        // Both children's boxes: the nearer is taken next (the left one on a tie), the other
        // waits below it.
        const uint left = node.first;
        const uint right = node.first + 1u;
        float t_left;
        float t_right;
        const bool hit_left = intersect_node(bvh_nodes_at(left), ray, inv_direction, t_range, t_left);
        const bool hit_right =
            intersect_node(bvh_nodes_at(right), ray, inv_direction, t_range, t_right);
        bvh_nodes_visited += 2u;
        if (hit_left && hit_right) {
            const bool right_nearer = t_right < t_left;
            stack_node[top] = right_nearer ? left : right;
            stack_t[top] = right_nearer ? t_left : t_right;
            stack_node[top + 1] = right_nearer ? right : left;
            stack_t[top + 1] = right_nearer ? t_right : t_left;
            top += 2;
        } else if (hit_left || hit_right) {
            stack_node[top] = hit_left ? left : right;
            stack_t[top] = hit_left ? t_left : t_right;
            top += 1;
        }
    }
    return found;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#bvh-traversal
    // return false;
    // END SOLUTION
}

// Whether anything is hit in t_range (shadow rays): stops at the first hit found.
bool bvh_intersect_any(Ray ray, Interval t_range) {
    // BEGIN SOLUTION
    Hit scratch = no_hit();
    bool found = false;
    for (int i = 0; i < primitive_counts.y && !found; ++i)
        found = intersect_primitive(primitive_id(kPlane, i), ray, t_range, scratch);
    const vec3 inv_direction = 1.0 / ray.direction;
    uint stack[kBvhMaxDepth + 1];  // nodes whose box the ray enters, still to open
    int top = 0;
    float t_entry;
    if (intersect_node(bvh_nodes_at(0), ray, inv_direction, t_range, t_entry)) {
        stack[0] = 0u;
        top = 1;
    }
    while (top > 0 && !found) {
        --top;
        const BvhNode node = bvh_nodes_at(stack[top]);
        if (node.count > 0u) {
            for (uint k = node.first; k < node.first + node.count && !found; ++k)
                found = intersect_primitive(int(bvh_primitives_at(k)), ray, t_range, scratch);
            continue;
        }
        // Any order will do; the right child is opened first.
        const uint left = node.first;
        const uint right = node.first + 1u;
        if (intersect_node(bvh_nodes_at(left), ray, inv_direction, t_range, t_entry)) {
            stack[top] = left;
            top += 1;
        }
        if (intersect_node(bvh_nodes_at(right), ray, inv_direction, t_range, t_entry)) {
            stack[top] = right;
            top += 1;
        }
    }
    return found;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#bvh-traversal
    // return false;
    // END SOLUTION
}
