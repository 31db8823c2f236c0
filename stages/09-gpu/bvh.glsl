// Stage 09, BVH traversal: stage 06's queries (stages/06-bvh/bvh.cpp) in GLSL, over the nodes
// the CPU built (bvh_nodes[], bvh_primitives[]: framework/accel/bvh.h). GLSL has no recursion
// and no pointers: a node is its index, and the nodes still to visit wait on a fixed-size stack
// (the builder never makes a tree deeper than kBvhMaxDepth). Planes stay outside the tree.
// Handout: stages/09-gpu/README.md#bvh-traversal.

const int kBvhMaxDepth = 64;

// Ray-box slab test for a node, as stage 06's intersect_node: true when the segment t_range
// meets the box, t_entry where it enters (clamped to t_range.min). Never miss a box a primitive
// inside it is hit in: widen the exit distance by the rounding bound, as stage 06 does.
bool intersect_node(BvhNode node, Ray ray, vec3 inv_direction, Interval t_range,
                    out float t_entry) {
    // BEGIN SOLUTION
    const float eps = 5.9604644775390625e-8;  // 2^-24
    const float growth = 1.0 + 2.0 * (3.0 * eps) / (1.0 - 3.0 * eps);
    float t0 = t_range.min, t1 = kInfinity;
    for (int axis = 0; axis < 3; ++axis) {
        const bool negative = inv_direction[axis] < 0.0;
        const float near_side = negative ? node.max[axis] : node.min[axis];
        const float far_side = negative ? node.min[axis] : node.max[axis];
        const float near = (near_side - ray.origin[axis]) * inv_direction[axis];
        const float far = (far_side - ray.origin[axis]) * inv_direction[axis];
        t0 = near > t0 ? near : t0;
        t1 = far < t1 ? far : t1;
    }
    t1 *= growth;
    t1 = t_range.max < t1 ? t_range.max : t1;
    t_entry = t0;
    return t0 <= t1;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/09-gpu/README.md#bvh-traversal");
    // t_entry = 0.0;
    // return false;
    // END SOLUTION
}

// BEGIN SOLUTION
// `left` when left_first, else `right`, field by field: WebGL's GLSL has no ?: on a struct.
BvhNode pick_child(bool left_first, BvhNode left, BvhNode right) {
    return BvhNode(left_first ? left.min : right.min, left_first ? left.first : right.first,
                   left_first ? left.max : right.max, left_first ? left.count : right.count);
}
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
    for (int i = 0; i < primitive_counts.y; ++i)
        if (intersect_primitive(primitive_id(kPlane, i), ray, t_range, hit)) {
            found = true;
            t_range.max = hit.t;
        }
    const vec3 inv_direction = 1.0 / ray.direction;
    // Invocations run in lock-step, 8 at a time on llvmpipe, and both sides of an `if` cost
    // all 8: so each descends to a leaf in an inner loop (one node a turn), then the 8 test
    // their leaves' primitives together. The node to visit next, the nearer child hit, stays in
    // `node` (already read for its box test); only the farther waits on the stack, since every
    // store to or load from a stack is a loop over the 8 lanes there.
    uint stack_node[kBvhMaxDepth + 1];
    float stack_t[kBvhMaxDepth + 1];
    int top = 0;
    float t_root;
    bvh_nodes_visited += 1u;
    BvhNode node = bvh_nodes[0];
    bool holding = intersect_node(node, ray, inv_direction, t_range, t_root);
    while (holding || top > 0) {
        // Descend until this invocation holds a leaf (or has nothing left to visit).
        uint first = 0u, count = 0u;
        while (holding || top > 0) {
            if (!holding) {
                --top;
                if (stack_t[top] > t_range.max) continue;  // a nearer hit was found after the push
                node = bvh_nodes[stack_node[top]];
            }
            holding = false;
            if (node.count > 0u) {
                first = node.first, count = node.count;
                break;
            }
            float t_left, t_right;
            bvh_nodes_visited += 2u;
            const BvhNode left = bvh_nodes[node.first], right = bvh_nodes[node.first + 1u];
            const bool hit_left = intersect_node(left, ray, inv_direction, t_range, t_left);
            const bool hit_right = intersect_node(right, ray, inv_direction, t_range, t_right);
            const bool left_first = !hit_right || (hit_left && t_left <= t_right);
            // The farther waits if both are hit (its slot is written either way: one store
            // without an `if` costs llvmpipe less than one behind it).
            stack_node[top] = node.first + (left_first ? 1u : 0u);
            stack_t[top] = left_first ? t_right : t_left;
            top += hit_left && hit_right ? 1 : 0;
            holding = hit_left || hit_right;
            node = pick_child(left_first, left, right);  // the nearer child hit
        }
        // Then its primitives, together with the other invocations that hold one.
        for (uint k = first; k < first + count; ++k)
            if (intersect_primitive(int(bvh_primitives[k]), ray, t_range, hit)) {
                found = true;
                t_range.max = hit.t;
            }
    }
    return found;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/09-gpu/README.md#bvh-traversal");
    // return false;
    // END SOLUTION
}

// Whether anything is hit in t_range (shadow rays): stops at the first hit found.
bool bvh_intersect_any(Ray ray, Interval t_range) {
    // BEGIN SOLUTION
    // No `return` inside a loop: llvmpipe pays for one there, so `found` ends the loops.
    Hit scratch = no_hit();
    bool found = false;
    for (int i = 0; i < primitive_counts.y && !found; ++i)
        found = intersect_primitive(primitive_id(kPlane, i), ray, t_range, scratch);
    const vec3 inv_direction = 1.0 / ray.direction;
    uint stack[kBvhMaxDepth + 1];
    int top = 0;
    float t_root;
    BvhNode node = bvh_nodes[0];
    bool holding = intersect_node(node, ray, inv_direction, t_range, t_root);
    // As bvh_intersect_nearest: descend to a leaf, nearer child first, then test it. Nearer
    // first pays here too (1.1x on large_icosphere): the 8 lanes' rays part less.
    while ((holding || top > 0) && !found) {
        uint first = 0u, count = 0u;
        while (holding || top > 0) {
            if (!holding) node = bvh_nodes[stack[--top]];
            holding = false;
            if (node.count > 0u) {
                first = node.first, count = node.count;
                break;
            }
            float t_left, t_right;
            const BvhNode left = bvh_nodes[node.first], right = bvh_nodes[node.first + 1u];
            const bool hit_left = intersect_node(left, ray, inv_direction, t_range, t_left);
            const bool hit_right = intersect_node(right, ray, inv_direction, t_range, t_right);
            const bool left_first = !hit_right || (hit_left && t_left <= t_right);
            stack[top] = node.first + (left_first ? 1u : 0u);  // the farther, kept if both hit
            top += hit_left && hit_right ? 1 : 0;
            holding = hit_left || hit_right;
            node = pick_child(left_first, left, right);  // the nearer child hit
        }
        for (uint k = first; k < first + count && !found; ++k)
            found = intersect_primitive(int(bvh_primitives[k]), ray, t_range, scratch);
    }
    return found;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/09-gpu/README.md#bvh-traversal");
    // return false;
    // END SOLUTION
}
