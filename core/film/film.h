// The image being rendered: per pixel, the weighted sum of radiance samples and of their
// filter weights, and the sums behind any AOVs asked for. Each pixel is written by one
// thread at a time (its tile's), in sample order, so the result does not depend on the
// thread count.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/denoise/denoise_input.h"
#include "core/film/aov.h"
#include "core/film/cryptomatte.h"
#include "core/image.h"
#include "core/math/vec.h"

namespace penumbra {

class Film {
public:
    // AOV buffers are allocated only for the AOVs in `aovs`.
    Film(int width, int height, AovSet aovs = {});
    int width() const { return m_width; }
    int height() const { return m_height; }
    const AovSet& aovs() const { return m_aovs; }
    // Adds a sample with filter weight w. Non-finite radiance is counted, not added.
    void add_sample(int x, int y, Spectrum L, float w);
    // The same, plus what the sample's camera ray hit, weighted by the same w: for a
    // film with AOVs (the loop without AOVs never pays for them).
    void add_sample(int x, int y, Spectrum L, float w, const AovRecord& aov);
    // Estimated variance of the pixel's beauty (the mean), per channel, from the two
    // halves of its samples: with A and B the halves' means and nA, nB their weights,
    // (A - B)^2 nA nB / (nA + nB)^2, unbiased when the halves are independent (each its
    // own randomised sample stream). 0 without the error AOV or with a half empty.
    Spectrum estimated_variance(int x, int y) const;
    // sqrt(mean over R, G, B of variance / (mean^2 + epsilon)): the relative standard
    // error that --target-error compares, matching relMSE's epsilon (kRelMseEpsilon).
    // With Aov::Coverage alpha is a fourth channel of the mean (its halves' variance).
    float relative_error(int x, int y) const;
    // Linear RGBA image. Alpha is 1, or with Aov::Coverage the weighted mean of the
    // samples' coverage, with the colour's weights (0 where the pixel has no samples); the
    // colour, whose misses count as zero, is then premultiplied by it.
    Image resolve() const;
    // One AOV's image: 3 channels (albedo, normal, position, variance), 4 (vector) or 1
    // (depth, samples, IDs). Albedo and normal average over all samples (a miss counts as
    // zero); depth, position and vector over the samples that hit (kNoHitDepth and 0 where
    // none did).
    // Error is relative_error (1 channel). The IDs are those of the sample nearest the
    // pixel's centre (the earliest of equally near ones), as exact integers in floats.
    // Cryptomatte gives 2 kCryptomatteRanks channels: per rank the ID (cryptomatte_float)
    // and its coverage (its samples' weight over all the pixel's), largest first.
    // Variance is that of the pixel's mean: the weighted sample variance over the
    // effective sample count (sum w)^2 / sum w^2, less one; 0 below two samples.
    Image resolve_aov(Aov aov) const;
    // What the denoiser reads, for a film with Aov::Denoise: the means of the even and of
    // the odd sample indices (the two sample streams) of the colour and of the guide
    // features, and the variance of each full mean by resolve_aov(Aov::Variance)'s
    // formula. A half without samples has mean 0.
    DenoiseInput denoise_input() const;
    uint64_t nonfinite_samples() const;

    // Every accumulator as raw bytes, by name, for checkpoints (job/checkpoint.h): a
    // buffer added to the film is listed here and so saved and restored with the rest.
    struct Buffer {
        const char* name;
        void* data;
        size_t bytes;
    };
    std::vector<Buffer> buffers();
    // The same list, to read from only.
    std::vector<Buffer> buffers() const { return const_cast<Film*>(this)->buffers(); }

    // Depth of a pixel that no sample hit (Cycles' background Z).
    static constexpr float kNoHitDepth = 1e10f;

private:
    using Sum3 = std::array<double, 3>;
    using Guide = std::array<double, kGuideChannels>;
    struct IdSample {
        float offset2 = std::numeric_limits<float>::infinity();  // no sample yet
        int32_t object = kNoHitId, material = kNoHitId;
    };
    // Structure of arrays: an AOV not asked for costs nothing but an empty vector.
    struct AovSums {
        std::vector<Sum3> albedo, normal, position, square;      // square: w L^2
        std::vector<double> weight, hit_weight, depth, weight2;  // weight2: w^2
        // Motion vectors: the sum of w times each hit sample's vector.
        std::vector<std::array<double, 4>> motion;
        std::vector<uint32_t> count;
        // Error estimate: the sums of the odd-indexed samples (the second half); the
        // first half is the pixel's total less these.
        std::vector<Sum3> odd;
        std::vector<double> odd_weight;
        // Denoising: the guide features' sums (w g), those of the odd-indexed samples and
        // the squares (w g^2), in denoise_input.h's channel order.
        std::vector<Guide> guide, guide_odd, guide_square;
        // Transparent background: the sum of w times the sample's coverage, and that of
        // the odd-indexed samples where the error estimate splits them.
        std::vector<double> coverage, coverage_odd;
        // ID layers: the IDs of the pixel's sample nearest its centre so far.
        std::vector<IdSample> ids;
        // Cryptomatte: each pixel's IDs and their weights.
        std::vector<CryptomatteSlots> crypto_object, crypto_material;
    };
    struct Pixel {
        double sum[3] = {0, 0, 0};
        double weight = 0;
        uint32_t nonfinite = 0;
    };
    int m_width, m_height;
    std::vector<Pixel> m_pixels;
    AovSet m_aovs;
    AovSums m_aov;
};

}  // namespace penumbra
