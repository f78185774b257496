// Pixel samplers. A sampler is positioned at (pixel, sample index) and then hands out
// sample dimensions in a fixed order; every value is a pure function of (seed, pixel,
// sample index, dimension), so any thread may render any pixel and get the same image.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "core/math/vec.h"
#include "core/sampling/permutation.h"
#include "core/sampling/rng.h"

namespace penumbra {

struct PixelCoord {
    int x = 0, y = 0;
};

class Sampler {
public:
    virtual ~Sampler() = default;
    virtual void start_pixel_sample(PixelCoord p, uint32_t sample_index) = 0;
    virtual float get_1d() = 0;
    virtual Vec2 get_2d() = 0;
    // The film position within the pixel (the first 2D dimension), in [0,1)^2.
    virtual Vec2 get_pixel_2d() = 0;
    // Takes the next 2D dimension without its value (a pinhole camera's lens sample), so
    // that the dimensions after it are the same whether or not it is read.
    virtual void skip_2d() { get_2d(); }
    virtual std::unique_ptr<Sampler> clone() const = 0;
    uint32_t samples_per_pixel() const { return m_spp; }

protected:
    Sampler(uint32_t spp, uint64_t seed) : m_spp(spp), m_seed(seed) {}
    uint32_t m_spp;
    uint64_t m_seed;
};

// Plain uniform random numbers: the baseline every other sampler must agree with.
class IndependentSampler final : public Sampler {
public:
    IndependentSampler(uint32_t spp, uint64_t seed) : Sampler(spp, seed) {}
    void start_pixel_sample(PixelCoord p, uint32_t sample_index) override;
    float get_1d() override { return m_rng.next_float(); }
    Vec2 get_2d() override { return {m_rng.next_float(), m_rng.next_float()}; }
    Vec2 get_pixel_2d() override { return get_2d(); }
    std::unique_ptr<Sampler> clone() const override {
        return std::make_unique<IndependentSampler>(*this);
    }

private:
    Rng m_rng;
};

// Jittered stratification per dimension: the spp samples of a pixel fall one per
// stratum (a nx * ny grid in 2D, nx * ny = spp), and the strata are shuffled
// independently for each dimension so dimensions do not correlate (pbrt-v4's
// StratifiedSampler, with Kensler's hashed permutation instead of stored tables).
class StratifiedSampler final : public Sampler {
public:
    StratifiedSampler(uint32_t spp, uint64_t seed);
    void start_pixel_sample(PixelCoord p, uint32_t sample_index) override;
    float get_1d() override;
    Vec2 get_2d() override;
    Vec2 get_pixel_2d() override { return get_2d(); }
    std::unique_ptr<Sampler> clone() const override {
        return std::make_unique<StratifiedSampler>(*this);
    }
    uint32_t strata_x() const { return m_nx; }
    uint32_t strata_y() const { return m_ny; }

private:
    uint64_t dimension_hash() const;
    uint32_t m_nx, m_ny;
    // What depends on spp alone, set up once: the strata permutation, the split of a 2D
    // stratum into (x, y), and 1/spp, 1/nx, 1/ny where exact (0 where not).
    HashedPermutation m_permutation;
    FixedDivisor m_columns;
    float m_inv_spp, m_inv_nx, m_inv_ny;
    uint64_t m_pixel_hash = 0;  // hash_values(seed, x, y), the prefix of every dimension's
    uint64_t m_stream = 0;      // the jitter's PCG stream, hash_values(seed, 2)
    uint32_t m_index = 0;
    uint32_t m_dimension = 0;
    Rng m_rng;
};

// Low discrepancy: each sample dimension (or pair) is an Owen-scrambled (0,2)-sequence,
// the first two Sobol dimensions, with the sample index shuffled per pixel and
// dimension (pbrt-v4's PaddedSobolSampler with Burley 2020's hash-based Owen
// scrambling). For power-of-two spp every pair of dimensions forms a (0,m,2)-net.
class SobolSampler final : public Sampler {
public:
    SobolSampler(uint32_t spp, uint64_t seed) : Sampler(spp, seed), m_permutation(spp) {}
    void start_pixel_sample(PixelCoord p, uint32_t sample_index) override;
    float get_1d() override;
    Vec2 get_2d() override;
    Vec2 get_pixel_2d() override { return get_2d(); }
    std::unique_ptr<Sampler> clone() const override {
        return std::make_unique<SobolSampler>(*this);
    }

private:
    uint64_t dimension_hash() const;
    HashedPermutation m_permutation;  // of the spp sample indices
    uint64_t m_pixel_hash = 0;        // hash_values(seed, x, y), the prefix of every dimension's
    uint32_t m_index = 0;
    uint32_t m_dimension = 0;
};

// The (0,2)-sequence: van der Corput and the second Sobol dimension, as 32-bit fractions.
uint32_t van_der_corput_bits(uint32_t i);
uint32_t sobol_second_dimension_bits(uint32_t i);
// Owen scrambling of a 32-bit fraction (Burley 2020's nested uniform scramble).
uint32_t owen_scramble(uint32_t v, uint32_t seed);

enum class SamplerType { Independent, Stratified, Sobol, ZSobol, TabledSobol };
// TabledSobol takes power-of-two spp (up to 2^16); for others it gives the stratified
// sampler.
std::unique_ptr<Sampler> make_sampler(SamplerType type, uint32_t spp, uint64_t seed);
// The sampler make_sampler gives for spp: what an image's header records.
SamplerType sampler_in_effect(SamplerType type, uint32_t spp);

}  // namespace penumbra
