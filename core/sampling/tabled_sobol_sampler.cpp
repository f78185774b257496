#include "core/sampling/tabled_sobol_sampler.h"

#include <algorithm>

#include "core/error.h"
#include "core/sampling/rng.h"
#include "core/sampling/zsobol_sampler.h"

namespace penumbra {

bool tabled_sobol_supports(uint32_t spp) {
    return spp > 0 && (spp & (spp - 1)) == 0 && spp <= TabledSobolSampler::kMaxSpp;
}

TabledSobolSampler::TabledSobolSampler(uint32_t spp, uint64_t seed) : Sampler(spp, seed) {
    CHECK(tabled_sobol_supports(spp));
    // The table count is a power of two, so table and index bits split sel cleanly; it is
    // at most 2^(16 - m), the bits sel has above the index's.
    const uint32_t tables =
        std::clamp(kTableEntries / spp, 1u, std::min(kMaxTables, kMaxSpp / spp));
    m_select_mask = tables * spp - 1;
    auto table = std::make_shared<std::vector<uint64_t>>(size_t(tables) * spp);
    std::vector<uint32_t> order(spp);
    for (uint32_t t = 0; t < tables; ++t) {
        Rng rng(hash_values(seed, 0x7ab1edull, t), hash_values(seed, 0x7ab1edull));
        const uint32_t seed_x = rng.next_u32(), seed_y = rng.next_u32();
        for (uint32_t i = 0; i < spp; ++i) order[i] = i;
        for (uint32_t i = spp; i > 1; --i) std::swap(order[i - 1], order[rng.next_below(i)]);
        for (uint32_t e = 0; e < spp; ++e) {
            const uint32_t i = order[e];
            // Owen-scrambled x = van der Corput, y = Sobol's second dimension; the low 8
            // bits are cleared: values are 24-bit fractions, and h's low bits choose
            // the entry instead of shifting.
            const uint32_t x = owen_scramble(van_der_corput_bits(i), seed_x) & ~0xffu;
            const uint32_t y = owen_scramble(sobol_second_dimension_bits(i), seed_y) & ~0xffu;
            (*table)[size_t(t) * spp + e] = x | uint64_t(y) << 32;
        }
    }
    m_table = std::move(table);
    m_entries = m_table->data();
}

void TabledSobolSampler::start_pixel_sample(PixelCoord p, uint32_t sample_index) {
    // A pixel's samples are drawn in a row: hash its coordinates once.
    if (p.x != m_pixel.x || p.y != m_pixel.y) {
        m_pixel = p;
        m_pixel_hash = hash_values(m_seed, p.x, p.y);
    }
    m_index = sample_index;
    m_key = m_pixel_hash;
}

}  // namespace penumbra
