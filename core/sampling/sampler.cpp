#include "core/sampling/sampler.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/sampling/hash.h"
#include "core/sampling/tabled_sobol_sampler.h"
#include "core/sampling/zsobol_sampler.h"

namespace penumbra {

void IndependentSampler::start_pixel_sample(PixelCoord p, uint32_t sample_index) {
    m_rng.seed(hash_values(m_seed, p.x, p.y, sample_index), hash_values(m_seed, 1));
}

namespace {

// 1/n where it is exact (n a power of two), for which x * (1/n) is x / n bitwise; else 0.
float exact_reciprocal(uint32_t n) { return (n & (n - 1)) == 0 ? 1.0f / float(n) : 0.0f; }

// x / n, as a multiply where the reciprocal is exact: a division is the costliest
// instruction of a dimension, and values stay those of the division.
inline float divide(float x, uint32_t n, float inv) { return inv != 0 ? x * inv : x / n; }

}  // namespace

StratifiedSampler::StratifiedSampler(uint32_t spp, uint64_t seed)
    : Sampler(spp, seed), m_permutation(spp) {
    // The most square factorization nx * ny = spp (a prime spp gives 1 x spp strips).
    m_nx = static_cast<uint32_t>(std::sqrt(static_cast<double>(spp)));
    while (m_nx > 1 && spp % m_nx != 0) --m_nx;
    m_nx = std::max(m_nx, 1u);
    m_ny = spp / m_nx;
    m_columns = FixedDivisor(m_nx);
    m_inv_spp = exact_reciprocal(spp);
    m_inv_nx = exact_reciprocal(m_nx);
    m_inv_ny = exact_reciprocal(m_ny);
    m_stream = hash_values(seed, 2);
}

void StratifiedSampler::start_pixel_sample(PixelCoord p, uint32_t sample_index) {
    m_pixel_hash = hash_values(m_seed, p.x, p.y);
    m_index = sample_index;
    m_dimension = 0;
    m_rng.seed(hash_combine(m_pixel_hash, sample_index), m_stream);
}

uint64_t StratifiedSampler::dimension_hash() const {
    // hash_values(seed, x, y, dimension): the fold's prefix is the pixel's hash.
    return hash_combine(m_pixel_hash, m_dimension);
}

float StratifiedSampler::get_1d() {
    const uint32_t stratum = m_permutation(m_index, static_cast<uint32_t>(dimension_hash()));
    ++m_dimension;
    return std::min(divide(stratum + m_rng.next_float(), m_spp, m_inv_spp), 0x1.fffffep-1f);
}

Vec2 StratifiedSampler::get_2d() {
    const uint32_t stratum = m_permutation(m_index, static_cast<uint32_t>(dimension_hash()));
    m_dimension += 2;
    const uint32_t sy = m_columns.div(stratum), sx = stratum - sy * m_nx;
    const float dx = m_rng.next_float(), dy = m_rng.next_float();
    return {std::min(divide(sx + dx, m_nx, m_inv_nx), 0x1.fffffep-1f),
            std::min(divide(sy + dy, m_ny, m_inv_ny), 0x1.fffffep-1f)};
}

uint32_t van_der_corput_bits(uint32_t i) {
    i = (i << 16) | (i >> 16);
    i = ((i & 0x00ff00ffu) << 8) | ((i & 0xff00ff00u) >> 8);
    i = ((i & 0x0f0f0f0fu) << 4) | ((i & 0xf0f0f0f0u) >> 4);
    i = ((i & 0x33333333u) << 2) | ((i & 0xccccccccu) >> 2);
    i = ((i & 0x55555555u) << 1) | ((i & 0xaaaaaaaau) >> 1);
    return i;
}

uint32_t sobol_second_dimension_bits(uint32_t i) {
    // Generator matrix of Sobol's second dimension: column k is v_k = v_{k-1} ^ (v_{k-1} >> 1).
    uint32_t r = 0;
    for (uint32_t v = 1u << 31; i; i >>= 1, v ^= v >> 1)
        if (i & 1) r ^= v;
    return r;
}

namespace {

// Laine-Karras style hash of a bit-reversed fraction: each output bit depends only on the
// bits below it (the fraction's more significant ones), which is what makes it an Owen
// scramble.
inline uint32_t laine_karras_hash(uint32_t x, uint32_t seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

float bits_to_float(uint32_t v) { return std::min(v * 0x1p-32f, 0x1.fffffep-1f); }

}  // namespace

uint32_t owen_scramble(uint32_t v, uint32_t seed) {
    return van_der_corput_bits(laine_karras_hash(van_der_corput_bits(v), seed));
}

void SobolSampler::start_pixel_sample(PixelCoord p, uint32_t sample_index) {
    m_pixel_hash = hash_values(m_seed, p.x, p.y);
    m_index = sample_index;
    m_dimension = 0;
}

uint64_t SobolSampler::dimension_hash() const {
    // hash_values(seed, x, y, dimension, 0x50b01), from the pixel's prefix.
    return hash_combine(hash_combine(m_pixel_hash, m_dimension), 0x50b01);
}

float SobolSampler::get_1d() {
    const uint64_t h = dimension_hash();
    ++m_dimension;
    const uint32_t index = m_permutation(m_index, static_cast<uint32_t>(h));
    // owen_scramble(van_der_corput_bits(index)) without the two reversals that cancel.
    return bits_to_float(
        van_der_corput_bits(laine_karras_hash(index, static_cast<uint32_t>(h >> 32))));
}

Vec2 SobolSampler::get_2d() {
    const uint64_t h = dimension_hash();
    m_dimension += 2;
    const uint32_t index = m_permutation(m_index, static_cast<uint32_t>(h));
    const uint64_t h2 = mix_bits(h);
    // As get_1d; the second dimension comes bit-reversed from five shift-xor steps rather
    // than the generator matrix's loop (the same values, see zsobol_sampler.h).
    return {bits_to_float(
                van_der_corput_bits(laine_karras_hash(index, static_cast<uint32_t>(h >> 32)))),
            bits_to_float(van_der_corput_bits(laine_karras_hash(
                sobol_second_dimension_reversed(index), static_cast<uint32_t>(h2))))};
}

std::unique_ptr<Sampler> make_sampler(SamplerType type, uint32_t spp, uint64_t seed) {
    switch (type) {
        case SamplerType::Independent:
            return std::make_unique<IndependentSampler>(spp, seed);
        case SamplerType::Stratified:
            return std::make_unique<StratifiedSampler>(spp, seed);
        case SamplerType::Sobol:
            return std::make_unique<SobolSampler>(spp, seed);
        case SamplerType::ZSobol:
            return std::make_unique<ZSobolSampler>(spp, seed);
        case SamplerType::TabledSobol:
            if (tabled_sobol_supports(spp)) return std::make_unique<TabledSobolSampler>(spp, seed);
            return std::make_unique<StratifiedSampler>(spp, seed);
    }
    throw std::invalid_argument("unknown sampler type");
}

SamplerType sampler_in_effect(SamplerType type, uint32_t spp) {
    return type == SamplerType::TabledSobol && !tabled_sobol_supports(spp) ? SamplerType::Stratified
                                                                           : type;
}

}  // namespace penumbra
