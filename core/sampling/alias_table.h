// Walker's alias method (with Vose's construction): O(1) sampling of a discrete
// distribution, used to choose lights by power.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace penumbra {

class AliasTable {
public:
    AliasTable() = default;
    // Weights need not be normalized; negative or non-finite weights count as 0. If all
    // weights are 0 the table is empty.
    explicit AliasTable(const std::vector<float>& weights);
    bool empty() const { return m_bins.empty(); }
    size_t size() const { return m_bins.size(); }
    // Index chosen with probability pmf(index), from one uniform u in [0,1). u_remapped
    // gets u rescaled to [0,1) within the part of [0,1) that chose the index: uniform and
    // independent of the choice, so it can serve as a further sample (pbrt-v4).
    // Inline: next-event estimation chooses a light on every bounce, and the caller's
    // pointers then become registers.
    uint32_t sample(float u, float* pmf = nullptr, float* u_remapped = nullptr) const {
        const float scaled = u * m_size;
        const uint32_t i = std::min(static_cast<uint32_t>(scaled), m_last);
        const float up = scaled - i;
        const Bin& bin = m_bins[i];
        if (m_equal) {
            // Every bin keeps itself (equal weights: one light, the Cornell box's two
            // triangles): no alias and no division; up / 1 is up.
            if (pmf) *pmf = bin.p;
            if (u_remapped) *u_remapped = std::min(up, 0x1.fffffep-1f);
            return i;
        }
        const uint32_t chosen = up < bin.q ? i : bin.alias;
        if (pmf) *pmf = m_bins[chosen].p;
        if (u_remapped) {
            // The alias branch only runs when q < 1 (up < 1 always).
            const float q = bin.q;
            *u_remapped = std::min(up < q ? up / q : (up - q) / (1 - q), 0x1.fffffep-1f);
        }
        return chosen;
    }
    float pmf(uint32_t index) const { return m_bins[index].p; }

private:
    struct Bin {
        float q = 0;         // probability of keeping this bin rather than its alias
        uint32_t alias = 0;
        float p = 0;         // normalized probability of this index
    };
    std::vector<Bin> m_bins;
    float m_size = 0;      // m_bins.size(), as sample scales u by it
    uint32_t m_last = 0;   // m_bins.size() - 1
    bool m_equal = false;  // every bin has q = 1 and is its own alias
};

}  // namespace penumbra
