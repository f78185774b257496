// Walker's alias method (with Vose's construction): O(1) sampling of a discrete
// distribution, used to choose lights by power.
#pragma once

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
    uint32_t sample(float u, float* pmf = nullptr, float* u_remapped = nullptr) const;
    float pmf(uint32_t index) const { return m_bins[index].p; }

private:
    struct Bin {
        float q = 0;         // probability of keeping this bin rather than its alias
        uint32_t alias = 0;
        float p = 0;         // normalized probability of this index
    };
    std::vector<Bin> m_bins;
};

}  // namespace penumbra
