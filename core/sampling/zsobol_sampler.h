// Owen-scrambled Sobol points in Morton (Z) order over the image: consecutive pixels take
// consecutive blocks of one (0,2)-sequence, so the error is spread as blue noise across
// pixels and each pixel's own samples stay a (0,m,2)-net (pbrt-v4's ZSobolSampler after
// Ahmed & Wonka 2020, with Burley 2020's hash-based Owen scrambling).
#pragma once

#include <array>
#include <cstdint>

#include "core/sampling/sampler.h"

namespace penumbra {

class ZSobolSampler final : public Sampler {
public:
    // Pixel coordinates are taken modulo kMaxResolution, a fixed bound (not the image's
    // size) so that a pixel's samples do not depend on the image, band or crop it is in.
    static constexpr uint32_t kMaxResolution = 1u << 16;
    ZSobolSampler(uint32_t spp, uint64_t seed);
    void start_pixel_sample(PixelCoord p, uint32_t sample_index) override;
    float get_1d() override;
    Vec2 get_2d() override;
    Vec2 get_pixel_2d() override { return get_2d(); }
    std::unique_ptr<Sampler> clone() const override {
        return std::make_unique<ZSobolSampler>(*this);
    }
    // The Sobol index that dimension `dimension` of the current sample uses (public for
    // tests): the Morton index with its base-4 digits shuffled per dimension; *scramble,
    // if given, receives the Owen scrambles' seeds (two 32-bit halves).
    uint64_t sobol_index(uint32_t dimension, uint64_t* scramble = nullptr);

private:
    // The shuffled digits above the sample index depend on the pixel and the dimension
    // alone: they (and the scramble seeds) are cached for the first kCachedDimensions
    // dimensions of the current pixel, whose samples the render loop draws in a row. A
    // cache: values do not depend on the order of calls.
    static constexpr uint32_t kCachedDimensions = 64;
    static constexpr int kLowPixelDigits = 8;  // 256 x 256 pixels
    uint64_t salt(uint32_t dimension) const;
    int first_pixel_digit() const;
    uint64_t pixel_digits(uint32_t dimension) const;
    uint64_t scramble_seed(uint32_t dimension, uint64_t pixel_digits) const;
    uint64_t m_pixel_morton = ~0ull;  // the pixel the cache is for
    std::array<uint64_t, kCachedDimensions> m_cached{}, m_cached_scramble{};
    std::array<bool, kCachedDimensions> m_cached_valid{};
    // The shuffled pixel digits from kLowPixelDigits up for a pixel below 256 x 256.
    std::array<uint64_t, kCachedDimensions> m_top{};
    int m_log2_spp = 0;
    int m_digits = 0;          // base-4 digits of the Morton index (pixel and sample)
    uint32_t m_seed_hash = 0;  // folded into every per-dimension hash
    uint64_t m_morton = 0;     // Morton code of the pixel, then the sample index
    uint32_t m_dimension = 0;
};

// Interleaves the low 16 bits of x (even bits) and y (odd bits).
uint32_t morton_2d(uint32_t x, uint32_t y);
// Sobol's second dimension, bit-reversed: the Pascal matrix mod 2 applied to i in five
// shift-xor steps, since (1 + y)^(2^s) = 1 + y^(2^s) over GF(2). Equals
// van_der_corput_bits(sobol_second_dimension_bits(i)).
uint32_t sobol_second_dimension_reversed(uint32_t i);
// A nested uniform (Owen) scramble of a bit-reversed fraction: every bit is flipped by a
// hash of the bits below it (the fraction's more significant bits). The constants are
// pbrt-v4's FastOwenScrambler (after Burley 2020 and Vegdahl's improved hash).
uint32_t owen_hash_reversed(uint32_t v, uint32_t seed);

}  // namespace penumbra
