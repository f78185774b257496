#include "core/sampling/zsobol_sampler.h"

#include <algorithm>

#include "core/error.h"
#include "core/sampling/hash.h"

namespace penumbra {

namespace {

// The 24 permutations of four digits.
constexpr uint8_t kPermutations[24][4] = {
    {0, 1, 2, 3}, {0, 1, 3, 2}, {0, 2, 1, 3}, {0, 2, 3, 1}, {0, 3, 2, 1}, {0, 3, 1, 2},
    {1, 0, 2, 3}, {1, 0, 3, 2}, {1, 2, 0, 3}, {1, 2, 3, 0}, {1, 3, 2, 0}, {1, 3, 0, 2},
    {2, 1, 0, 3}, {2, 1, 3, 0}, {2, 0, 1, 3}, {2, 0, 3, 1}, {2, 3, 0, 1}, {2, 3, 1, 0},
    {3, 1, 2, 0}, {3, 1, 0, 2}, {3, 2, 1, 0}, {3, 2, 0, 1}, {3, 0, 2, 1}, {3, 0, 1, 2}};

// A cheap 64-to-32-bit hash for choosing digit permutations: only its top bits are used.
inline uint32_t digit_hash(uint64_t v) {
    v *= 0xd6e8feb86659fd93ULL;
    v ^= v >> 32;
    v *= 0xd6e8feb86659fd93ULL;
    return static_cast<uint32_t>(v >> 32);
}

inline uint32_t reverse_bits(uint32_t i) {
    i = (i << 16) | (i >> 16);
    i = ((i & 0x00ff00ffu) << 8) | ((i & 0xff00ff00u) >> 8);
    i = ((i & 0x0f0f0f0fu) << 4) | ((i & 0xf0f0f0f0u) >> 4);
    i = ((i & 0x33333333u) << 2) | ((i & 0xccccccccu) >> 2);
    i = ((i & 0x55555555u) << 1) | ((i & 0xaaaaaaaau) >> 1);
    return i;
}

// 24 bits in [0, 1): the largest float below 1 is the top of the range.
inline float to_unit_float(uint32_t bits) { return (bits >> 8) * 0x1p-24f; }

inline uint32_t part_bits(uint32_t x) {
    x &= 0xffffu;
    x = (x | (x << 8)) & 0x00ff00ffu;
    x = (x | (x << 4)) & 0x0f0f0f0fu;
    x = (x | (x << 2)) & 0x33333333u;
    x = (x | (x << 1)) & 0x55555555u;
    return x;
}

// Ahmed & Wonka's hierarchical shuffle of the base-4 digits of `morton` from digit
// `last` up to digit `first`: each digit is permuted by a choice that depends on the
// digits above it and the dimension's salt, so sibling quads of pixels (and a pixel's
// samples) take their blocks of the sequence in a random order. An odd log2(spp) shifts
// the digits by one bit (the bottom one is base 2).
inline uint64_t shuffle_digits(uint64_t morton, uint64_t salt, int first, int last, int odd) {
    uint64_t index = 0;
    for (int i = first; i >= last; --i) {
        const int shift = 2 * i - odd;
        const uint32_t digit = (morton >> shift) & 3;
        const uint64_t higher = morton >> (shift + 2);
        // (h * 24) >> 32 picks one of 24 permutations without a division.
        const uint32_t p = uint32_t((uint64_t(digit_hash(higher ^ salt)) * 24) >> 32);
        index |= uint64_t(kPermutations[p][digit]) << shift;
    }
    return index;
}

}  // namespace

uint32_t morton_2d(uint32_t x, uint32_t y) { return part_bits(x) | (part_bits(y) << 1); }

uint32_t sobol_second_dimension_reversed(uint32_t i) {
    // Bit k of i is the coefficient of z^k in I(z); the result is I(1 + y), computed one
    // bit of k at a time: a term z^k with bit s set also lands on z^(k - 2^s).
    i ^= (i & 0xaaaaaaaau) >> 1;
    i ^= (i & 0xccccccccu) >> 2;
    i ^= (i & 0xf0f0f0f0u) >> 4;
    i ^= (i & 0xff00ff00u) >> 8;
    i ^= (i & 0xffff0000u) >> 16;
    return i;
}

uint32_t owen_hash_reversed(uint32_t v, uint32_t seed) {
    // Multiplications and additions carry only towards higher bits, so bit k depends on
    // bits 0..k alone: a nested scramble of the fraction's leading digits.
    v ^= v * 0x3d20adeau;
    v += seed;
    v *= (seed >> 16) | 1u;
    v ^= v * 0x05526c56u;
    v ^= v * 0x53a22864u;
    return v;
}

ZSobolSampler::ZSobolSampler(uint32_t spp, uint64_t seed) : Sampler(spp, seed) {
    while ((1u << m_log2_spp) < std::max(spp, 1u)) ++m_log2_spp;
    // 16 levels of pixels and ceil(log2(spp) / 2) of samples (an odd log2 leaves one
    // base-2 digit at the bottom).
    m_digits = 16 + (m_log2_spp + 1) / 2;
    m_seed_hash = static_cast<uint32_t>(mix_bits(seed ^ 0x250b01u));
    const int odd = m_log2_spp & 1, top = first_pixel_digit() + kLowPixelDigits;
    for (uint32_t d = 0; d < kCachedDimensions; ++d)
        m_top[d] = shuffle_digits(0, salt(d), m_digits - 1, top, odd);
}

void ZSobolSampler::start_pixel_sample(PixelCoord p, uint32_t sample_index) {
    // An index past the budget would overwrite the pixel's digits and repeat another
    // pixel's samples.
    CHECK(uint64_t(sample_index) >> m_log2_spp == 0,
          << "sample " << sample_index << " of a " << m_spp << " spp sampler");
    const uint64_t pixel = morton_2d(uint32_t(p.x), uint32_t(p.y));
    if (pixel != m_pixel_morton) {
        m_pixel_morton = pixel;
        m_cached_valid.fill(false);
    }
    m_morton = (pixel << m_log2_spp) | sample_index;
    m_dimension = 0;
}

uint64_t ZSobolSampler::salt(uint32_t dimension) const {
    return (uint64_t(m_seed_hash) << 32) ^ (0x9e3779b97f4a7c15ULL * (dimension + 1));
}

int ZSobolSampler::first_pixel_digit() const {
    // The lowest digit whose bits all lie above the sample index: 2 i - odd >= log2(spp).
    return (m_log2_spp + (m_log2_spp & 1)) / 2;
}

uint64_t ZSobolSampler::pixel_digits(uint32_t dimension) const {
    const int odd = m_log2_spp & 1, first = first_pixel_digit();
    // Below 256 x 256 pixels the top 8 pixel digits and all above them are 0, so their
    // shuffle depends on the dimension alone (m_top, the same function evaluated once).
    const int top = first + kLowPixelDigits;
    if (dimension < kCachedDimensions && (m_morton >> (2 * top - odd)) == 0)
        return m_top[dimension] | shuffle_digits(m_morton, salt(dimension), top - 1, first, odd);
    return shuffle_digits(m_morton, salt(dimension), m_digits - 1, first, odd);
}

uint64_t ZSobolSampler::scramble_seed(uint32_t dimension, uint64_t pixel_digits) const {
    // Index bits from 32 up (pixel digits only) would only touch fraction bits below
    // 2^-32: they select the scramble instead, so every 2^32-block of the sequence is
    // scrambled on its own.
    return mix_bits(((uint64_t(m_seed_hash) << 32) | dimension) ^
                    ((pixel_digits >> 32) * 0x9e3779b97f4a7c15ULL));
}

uint64_t ZSobolSampler::sobol_index(uint32_t dimension, uint64_t* scramble) {
    const int odd = m_log2_spp & 1;
    uint64_t index, seed;
    if (dimension < kCachedDimensions) {
        if (!m_cached_valid[dimension]) {
            m_cached[dimension] = pixel_digits(dimension);
            m_cached_scramble[dimension] = scramble_seed(dimension, m_cached[dimension]);
            m_cached_valid[dimension] = true;
        }
        index = m_cached[dimension];
        seed = m_cached_scramble[dimension];
    } else {
        index = pixel_digits(dimension);
        seed = scramble_seed(dimension, index);
    }
    const uint64_t s = salt(dimension);
    index |= shuffle_digits(m_morton, s, first_pixel_digit() - 1, odd, odd);
    if (odd) index |= (m_morton & 1) ^ (digit_hash((m_morton >> 1) ^ s) >> 31);
    if (scramble) *scramble = seed;
    return index;
}

float ZSobolSampler::get_1d() {
    uint64_t h;
    const uint64_t index = sobol_index(m_dimension, &h);
    ++m_dimension;
    // Dimension 0 of Sobol is van der Corput: bit-reversed, it is the index itself.
    return to_unit_float(reverse_bits(owen_hash_reversed(uint32_t(index), uint32_t(h))));
}

Vec2 ZSobolSampler::get_2d() {
    uint64_t h;
    const uint32_t i = uint32_t(sobol_index(m_dimension, &h));
    m_dimension += 2;
    return {to_unit_float(reverse_bits(owen_hash_reversed(i, uint32_t(h)))),
            to_unit_float(reverse_bits(
                owen_hash_reversed(sobol_second_dimension_reversed(i), uint32_t(h >> 32))))};
}

}  // namespace penumbra
