// A bounding volume hierarchy over lights for choosing one in proportion to its estimated
// contribution at a receiver (Conty Estevez & Kulla 2018, "Importance sampling of many
// lights with adaptive tree splitting"; pbrt-v4's BVHLightSampler).
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
    // out. Built top-down with pbrt-v4's surface-area-orientation cost in 12 buckets per
    // axis, one light per leaf; below depth 32, median splits keep every trail in 64 bits.
    explicit LightBvh(std::vector<std::pair<uint32_t, LightBounds>> lights);
    bool empty() const { return m_nodes.empty(); }
    size_t node_count() const { return m_nodes.size(); }

    // One light (the caller's index) and the probability of choosing it, descending by
    // the children's importance at (p, n); u in [0,1). Empty when nothing can reach p.
    std::optional<std::pair<uint32_t, float>> sample(Vec3 p, Vec3 n, float u) const;
    // Probability that sample(p, n, .) returns light; 0 for a light not in the tree. Walks
    // the light's bit trail from the root (pbrt-v4), so it costs one descent.
    float pmf(Vec3 p, Vec3 n, uint32_t light) const;

private:
    struct Node {
        LightBounds bounds;
        uint32_t index = 0;  // interior: the second child (the first follows the node);
                             // leaf: the caller's light index
        bool leaf = false;
    };
    uint32_t build(std::vector<std::pair<uint32_t, LightBounds>>& lights, size_t begin, size_t end,
                   int depth, uint64_t trail);
    // Importances of the two children of interior node i, in order.
    std::pair<float, float> child_importance(uint32_t i, Vec3 p, Vec3 n) const;

    std::vector<Node> m_nodes;
    // Per caller index: the branch taken at each depth (bit d: second child at depth d),
    // or kNotInTree.
    std::vector<uint64_t> m_trail;
    static constexpr uint64_t kNotInTree = ~uint64_t(0);
};

}  // namespace penumbra
