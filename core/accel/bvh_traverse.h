// Stack traversal of a flattened BVH (bvh_build.h), shared by the object BVHs and the
// instance level: the caller supplies what a leaf does.
#pragma once

#include <cstdint>

#include "core/accel/bvh_build.h"
#include "core/accel/ray_box.h"

namespace penumbra {

// Visits the leaves of `nodes` whose boxes the ray reaches within [r.tmin, tmax], the
// nearer child first: by the sign of the direction on the node's split axis, the child
// on the side the ray comes from (the first child holds the smaller centroids). leaf(
// first, count, tmax) may shrink tmax (closest hit), which culls the boxes behind it,
// and returns true to stop (any hit).
template <class Leaf>
inline void traverse_bvh(const BvhNode* nodes, const RayBoxPrecomp& r, float& tmax, Leaf&& leaf) {
    if (!nodes || !r.valid) return;
    uint32_t stack[kBvhStackSize];
    int sp = 0;
    uint32_t i = 0;
    for (;;) {
        const BvhNode& n = nodes[i];
        float t_enter;
        if (ray_box(n.lo, n.hi, r, tmax, &t_enter)) {
            if (!n.is_leaf()) {
                if (r.neg[n.axis]) {
                    stack[sp++] = i + 1;
                    i = n.offset;
                } else {
                    stack[sp++] = n.offset;
                    i = i + 1;
                }
                continue;
            }
            if (leaf(n.offset, uint32_t(n.count), tmax)) return;
        }
        if (sp == 0) return;
        i = stack[--sp];
    }
}

}  // namespace penumbra
