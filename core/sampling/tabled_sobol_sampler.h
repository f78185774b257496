// A cheap low-discrepancy sampler: each pixel's samples in each dimension (or pair) are
// one of a few Owen-scrambled (0,2)-nets tabulated once per sampler, with the sample
// index xor-ed with a key and the values digitally shifted per (pixel, dimension). Costs
// one 64-bit hash, one load and an xor per dimension or pair, where the stratified and
// Sobol samplers evaluate a hashed permutation and PCG steps or Owen hashes
// (docs/performance.md, "A tabled Sobol sampler").
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/sampling/hash.h"
#include "core/sampling/sampler.h"

namespace penumbra {

// For spp a power of two up to kMaxSpp (make_sampler gives the stratified sampler
// otherwise). Dimension d of sample i of pixel (x, y), with h = mix_bits(hash_values(seed,
// x, y) + d * 0x9e3779b97f4a7c15) (SplitMix64 seeded by the pixel), is
//   w = table[sel(h) ^ i] ^ h,  sel(h) = (bits 0-7 of h | bits 32-39 of h << 8) & mask,
// the 2D value (bits 8-31 of w, bits 40-63 of w) as 24-bit fractions, the 1D value the
// first. The table holds kTableEntries / spp (at most 2^(16 - m)) tables of the spp points
// of the (0,2)-sequence, each Owen-scrambled and stored in a random order (both fixed by
// the seed); sel's low m bits xor the index (a bijection of [0, spp)), its high bits pick
// the table. So:
// - every pixel's spp samples of a dimension pair are a digitally shifted scrambled
//   (0,m,2)-net, and of one dimension one per stratum of 1/spp;
// - one sample's values are uniform and independent across dimensions: the shift is
//   h's bits 8-31 and 40-63, independent of the bits that chose the entry;
// - dimensions decorrelate through the random table orders, the xor keys and the shifts.
class TabledSobolSampler final : public Sampler {
public:
    static constexpr uint32_t kMaxSpp = 1u << 16;
    static constexpr uint32_t kTableEntries = 2048;  // 16 KiB: stays in L1 with the rest
    static constexpr uint32_t kMaxTables = 64;
    static constexpr uint64_t kGolden = 0x9e3779b97f4a7c15ull;
    TabledSobolSampler(uint32_t spp, uint64_t seed);
    void start_pixel_sample(PixelCoord p, uint32_t sample_index) override;
    float get_1d() override {
        const uint64_t w = entry();
        m_key += kGolden;
        return (uint32_t(w) >> 8) * 0x1p-24f;
    }
    Vec2 get_2d() override {
        const uint64_t w = entry();
        m_key += 2 * kGolden;
        return {(uint32_t(w) >> 8) * 0x1p-24f, uint32_t(w >> 40) * 0x1p-24f};
    }
    Vec2 get_pixel_2d() override { return get_2d(); }
    void skip_2d() override { m_key += 2 * kGolden; }
    // A 1D value whose use depends on what the caller draws next (the light choice of a
    // light sampler that does not remap): skip_1d() takes its dimension, and value_1d()
    // of what it returned gives the value that get_1d() would have, when it is needed.
    uint64_t skip_1d() {
        const uint64_t key = m_key;
        m_key += kGolden;
        return key;
    }
    float value_1d(uint64_t skipped) const { return (uint32_t(entry(skipped)) >> 8) * 0x1p-24f; }
    std::unique_ptr<Sampler> clone() const override {
        return std::make_unique<TabledSobolSampler>(*this);
    }
    // The number of scrambled tables, and entry e (< tables() * spp) of them (for tests):
    // x in the low 32 bits, y in the high, each with its low 8 bits zero.
    uint32_t tables() const { return m_select_mask / m_spp + 1; }
    uint64_t table_entry(uint32_t e) const { return (*m_table)[e]; }

private:
    uint64_t entry() const { return entry(m_key); }
    uint64_t entry(uint64_t key) const {
        const uint64_t h = mix_bits(key);
        const uint32_t sel = (uint32_t(h) & 0xffu) | (uint32_t(h >> 24) & 0xff00u);
        return m_entries[(sel ^ m_index) & m_select_mask] ^ h;
    }
    std::shared_ptr<const std::vector<uint64_t>> m_table;
    // m_table's data, which the shared table keeps alive for every copy: one load less
    // per draw than through the shared pointer and the vector.
    const uint64_t* m_entries = nullptr;
    uint32_t m_select_mask = 0;  // tables() * spp - 1
    uint32_t m_index = 0;
    PixelCoord m_pixel{-1, -1};
    uint64_t m_pixel_hash = 0;
    uint64_t m_key = 0;  // the pixel's hash + dimension * kGolden
};

// Whether spp suits the tabled sampler: a power of two no greater than kMaxSpp.
bool tabled_sobol_supports(uint32_t spp);

}  // namespace penumbra
