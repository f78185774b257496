// Top-down construction of a bounding volume hierarchy over primitive boxes, flattened
// into a depth-first array of 32-byte nodes. Shared by the per-object BVHs and the
// instance level; the primitives themselves (triangles, instances) stay with the caller.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/math/bounds.h"

namespace penumbra {

// How an interior node's primitives are divided, by their box centroids:
//   Center: at the middle of the centroid bounds' largest axis (the classic spatial
//           median; cheap, poor on uneven distributions).
//   Median: equal counts on the same axis (std::nth_element; balanced, depth log2 N).
//   Sah:    the binned surface area heuristic (Wald 2007, "On fast Construction of
//           SAH-based Bounding Volume Hierarchies"; MacDonald & Booth 1990): 32 bins per
//           axis on all three axes, the plane of least expected cost, or a leaf when that
//           is cheaper.
enum class BvhSplit { Sah, Median, Center };
std::string bvh_split_name(BvhSplit split);

// SAH cost constants, relative: visiting one node and intersecting one triangle. On
// incoherent rays traversal waits on memory: a node visit is usually a cache miss, while
// a leaf's triangles are contiguous, so a triangle counts half a node. Against 1:1 this
// gave trees with 35% fewer nodes (1M-triangle sphere) and 2-3 triangles per leaf, at
// the same speed within our measurement noise. Expected cost of a tree = sum over
// interior nodes of P(node) * traversal + sum over leaves of P(leaf) * count *
// intersection, with P = surface area / the root's surface area (MacDonald & Booth).
constexpr float kSahTraversalCost = 1.0f;
constexpr float kSahIntersectionCost = 0.5f;
constexpr int kSahBins = 32;
// Leaf sizes. Center and median split until a node has at most kSplitLeafSize
// primitives. SAH stops where a leaf is cheaper than any split, but never keeps more than
// kMaxLeafSize primitives in a leaf (a larger node is split even at a loss).
constexpr uint32_t kSplitLeafSize = 4;
constexpr uint32_t kMaxLeafSize = 8;
// Below this depth every strategy switches to the median split, whose depth is at most
// log2 N more: traversal stacks of kBvhStackSize entries can never overflow.
constexpr int kMedianBelowDepth = 64;
constexpr int kBvhStackSize = 128;

struct BvhNode {
    float lo[3], hi[3];
    // Interior: index of the second child (the first child is the next node).
    // Leaf: index of its first primitive in BvhTree::order.
    uint32_t offset;
    uint16_t count;  // primitives in a leaf; 0 for an interior node
    uint8_t axis;    // interior: the split axis, to visit the nearer child first
    uint8_t pad;
    bool is_leaf() const { return count != 0; }
};
static_assert(sizeof(BvhNode) == 32, "BVH nodes are 32 bytes, two to a cache line");

struct BvhTree {
    std::vector<BvhNode> nodes;   // depth-first; nodes[0] is the root; empty: no primitives
    std::vector<uint32_t> order;  // leaf slot -> input primitive index
    int depth = 0;                // levels below the root
};

// Builds over the given primitive boxes (empty boxes are not allowed: skip such
// primitives before). Single-threaded.
BvhTree build_bvh(const std::vector<Bounds3>& prim_bounds, BvhSplit split);

// The SAH expected cost of a built tree with the constants above (0 for an empty tree).
double sah_cost(const BvhTree& tree);

inline float surface_area(const Bounds3& b) {
    if (b.empty()) return 0;
    const Vec3 d = b.diagonal();
    return 2 * (d.x * d.y + d.y * d.z + d.z * d.x);
}

}  // namespace penumbra
