// Pixel samplers. A sampler is positioned at (pixel, sample index) and then hands out
// sample dimensions in a fixed order; every value is a pure function of (seed, pixel,
// sample index, dimension), so any thread may render any pixel and get the same image.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "core/math/vec.h"
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
    PixelCoord m_pixel;
    uint32_t m_index = 0;
    uint32_t m_dimension = 0;
    Rng m_rng;
};

// Element i of a pseudo-random permutation of [0, n) selected by key (Kensler 2013,
// "Correlated Multi-Jittered Sampling", the cycle-walking hash permutation).
uint32_t permutation_element(uint32_t i, uint32_t n, uint32_t key);

enum class SamplerType { Independent, Stratified };
std::unique_ptr<Sampler> make_sampler(SamplerType type, uint32_t spp, uint64_t seed);
// "independent" | "stratified"; throws std::invalid_argument otherwise.
SamplerType parse_sampler_type(const std::string& name);

}  // namespace penumbra
