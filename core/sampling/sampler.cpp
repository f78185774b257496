#include "core/sampling/sampler.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/sampling/hash.h"

namespace penumbra {

void IndependentSampler::start_pixel_sample(PixelCoord p, uint32_t sample_index) {
    m_rng.seed(hash_values(m_seed, p.x, p.y, sample_index), hash_values(m_seed, 1));
}

uint32_t permutation_element(uint32_t i, uint32_t l, uint32_t p) {
    uint32_t w = l - 1;
    w |= w >> 1;
    w |= w >> 2;
    w |= w >> 4;
    w |= w >> 8;
    w |= w >> 16;
    do {
        i ^= p;
        i *= 0xe170893d;
        i ^= p >> 16;
        i ^= (i & w) >> 4;
        i ^= p >> 8;
        i *= 0x0929eb3f;
        i ^= p >> 23;
        i ^= (i & w) >> 1;
        i *= 1 | p >> 27;
        i *= 0x6935fa69;
        i ^= (i & w) >> 11;
        i *= 0x74dcb303;
        i ^= (i & w) >> 2;
        i *= 0x9e501cc3;
        i ^= (i & w) >> 2;
        i *= 0xc860a3df;
        i &= w;
        i ^= i >> 5;
    } while (i >= l);
    return (i + p) % l;
}

StratifiedSampler::StratifiedSampler(uint32_t spp, uint64_t seed) : Sampler(spp, seed) {
    // The most square factorization nx * ny = spp (a prime spp gives 1 x spp strips).
    m_nx = static_cast<uint32_t>(std::sqrt(static_cast<double>(spp)));
    while (m_nx > 1 && spp % m_nx != 0) --m_nx;
    m_nx = std::max(m_nx, 1u);
    m_ny = spp / m_nx;
}

void StratifiedSampler::start_pixel_sample(PixelCoord p, uint32_t sample_index) {
    m_pixel = p;
    m_index = sample_index;
    m_dimension = 0;
    m_rng.seed(hash_values(m_seed, p.x, p.y, sample_index), hash_values(m_seed, 2));
}

uint64_t StratifiedSampler::dimension_hash() const {
    return hash_values(m_seed, m_pixel.x, m_pixel.y, m_dimension);
}

float StratifiedSampler::get_1d() {
    const uint32_t stratum =
        permutation_element(m_index, m_spp, static_cast<uint32_t>(dimension_hash()));
    ++m_dimension;
    return std::min((stratum + m_rng.next_float()) / m_spp, 0x1.fffffep-1f);
}

Vec2 StratifiedSampler::get_2d() {
    const uint32_t stratum =
        permutation_element(m_index, m_spp, static_cast<uint32_t>(dimension_hash()));
    m_dimension += 2;
    const uint32_t sx = stratum % m_nx, sy = stratum / m_nx;
    const float dx = m_rng.next_float(), dy = m_rng.next_float();
    return {std::min((sx + dx) / m_nx, 0x1.fffffep-1f),
            std::min((sy + dy) / m_ny, 0x1.fffffep-1f)};
}

std::unique_ptr<Sampler> make_sampler(SamplerType type, uint32_t spp, uint64_t seed) {
    switch (type) {
        case SamplerType::Independent:
            return std::make_unique<IndependentSampler>(spp, seed);
        case SamplerType::Stratified:
            return std::make_unique<StratifiedSampler>(spp, seed);
    }
    throw std::invalid_argument("unknown sampler type");
}

SamplerType parse_sampler_type(const std::string& name) {
    if (name == "independent") return SamplerType::Independent;
    if (name == "stratified") return SamplerType::Stratified;
    throw std::invalid_argument("unknown sampler '" + name +
                                "' (expected independent or stratified)");
}

}  // namespace penumbra
