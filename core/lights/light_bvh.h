// A bounding volume hierarchy over lights for choosing one in proportion to its estimated
// contribution at a receiver (Conty Estevez & Kulla 2018, "Importance sampling of many
// lights with adaptive tree splitting"; pbrt-v4's BVHLightSampler), four children a node
// so that one pass of 4-wide SIMD weighs all of them and the descent is half as deep.
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
    // collapsed: a node's children are its binary children's children.
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

    // The importances node's four children get at (p, n) (0 for an empty slot); exposed
    // for the tests, which hold them against LightBounds::importance.
    void child_importance(uint32_t node, Vec3 p, Vec3 n, float out[4]) const;

    // What a node is, structure of arrays over its four children: the bounds the
    // importance reads, precomputed (centroid, squared half-diagonal, sin theta_o) so the
    // descent does no trigonometry and no per-box work.
    struct alignas(16) Node {
        float cx[4], cy[4], cz[4];  // box centroid
        float r2[4];                // squared half-diagonal of the box
        float phi[4];               // 0: empty slot
        float wx[4], wy[4], wz[4];  // cone axis
        float cos_o[4], sin_o[4];   // cone of normals
        float cos_e[4];             // emission spread
        uint32_t two_sided[4];      // sign-bit mask: emits about -w as well
        uint32_t child[4];          // interior: node index; leaf: the caller's light index
        uint32_t leaf_mask = 0;     // bit k: child k is a light
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

    std::vector<BinaryNode> m_binary;  // only while building
    std::vector<Node> m_nodes;
    // Per caller index: the child slot taken at each depth (bits 2d, 2d+1), or kNotInTree.
    std::vector<uint64_t> m_trail;
    static constexpr uint64_t kNotInTree = ~uint64_t(0);
};

}  // namespace penumbra
