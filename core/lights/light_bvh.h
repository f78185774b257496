// A bounding volume hierarchy over lights for choosing one in proportion to its estimated
// contribution at a receiver (Conty Estevez & Kulla 2018, "Importance sampling of many
// lights with adaptive tree splitting"; pbrt-v4's BVHLightSampler), four children a node
// so that one pass of 4-wide SIMD weighs all of them and the descent is half as deep.
// (Eight children, two passes a node, measured slower: the square roots, not the depth,
// bound a descent; docs/performance.md.)
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "core/lights/light_bounds.h"

namespace penumbra {

class LightBvh {
public:
    LightBvh() = default;
    // lights: (the caller's index of a light, its bounds). Lights of zero power are left
    // out. Built top-down as a binary tree with pbrt-v4's surface-area-orientation cost in
    // 12 buckets per axis, one light per leaf (below depth 32, median splits), then
    // collapsed: a node's children are its binary descendants kLevels levels down (or the
    // leaves above them).
    explicit LightBvh(std::vector<std::pair<uint32_t, LightBounds>> lights);
    bool empty() const { return m_nodes.empty(); }
    size_t node_count() const { return m_nodes.size(); }

    // One light (the caller's index) and the probability of choosing it, descending by
    // the children's importance at (p, n); u in [0,1). Empty when nothing can reach p.
    std::optional<std::pair<uint32_t, float>> sample(Vec3 p, Vec3 n, float u) const;
    // Probability that sample(p, n, .) returns light; 0 for a light not in the tree. Walks
    // the light's trail of child slots from the root with the same arithmetic as sample(),
    // so the two agree exactly.
    float pmf(Vec3 p, Vec3 n, uint32_t light) const;

    static constexpr int kLevels = 2;            // binary levels a node holds
    static constexpr int kWidth = 1 << kLevels;  // children a node (a multiple of 4)

    // The importances node's children get at (p, n) (0 for an empty slot); exposed for
    // the tests, which hold them against LightBounds::importance.
    void child_importance(uint32_t node, Vec3 p, Vec3 n, float out[kWidth]) const;

    // What a node is, structure of arrays over its children: the bounds the importance
    // reads, precomputed (centroid, squared half-diagonal, sin theta_o) so the descent
    // does no trigonometry and no per-box work.
    struct alignas(16) Node {  // 16: the SSE loads of importance4
        float cx[kWidth], cy[kWidth], cz[kWidth];  // box centroid
        float r[kWidth], r2[kWidth];               // half-diagonal of the box, its square
        float inv_r2[kWidth];                      // 1 / max(r2, 1e-20)
        float phi[kWidth];                         // 0: empty slot
        float wx[kWidth], wy[kWidth], wz[kWidth];  // cone axis
        float cos_o[kWidth], sin_o[kWidth];        // cone of normals
        float cos_e[kWidth];                       // emission spread
        uint32_t two_sided[kWidth];  // sign-bit mask: emits about -w as well
        uint32_t child[kWidth];      // interior: node index; leaf: the caller's light index
        uint32_t leaf_mask = 0;      // bit k: child k is a light
    };

    const Node& node(uint32_t i) const { return m_nodes[i]; }

private:
    struct BinaryNode {
        LightBounds bounds;
        uint32_t index = 0;  // interior: the second child (the first follows); leaf: light
        bool leaf = false;
    };
    uint32_t build(std::vector<std::pair<uint32_t, LightBounds>>& lights, size_t begin, size_t end,
                   int depth);
    uint32_t collapse(uint32_t binary, int depth, uint64_t trail);
    // Appends to slots the binary descendants of `binary` `levels` levels down, or the
    // leaves above them.
    void gather(uint32_t binary, int levels, uint32_t* slots, int* count) const;

    std::vector<BinaryNode> m_binary;  // only while building
    std::vector<Node> m_nodes;
    // Per caller index: the child slot taken at each depth (kLevels bits a depth, from
    // bit 0), or kNotInTree.
    std::vector<uint64_t> m_trail;
    static constexpr uint64_t kNotInTree = ~uint64_t(0);
};

}  // namespace penumbra
