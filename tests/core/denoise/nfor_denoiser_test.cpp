// The denoiser on images whose truth is known: a checkered texture (albedo edges) under
// a light gradient with a hard shadow edge, plus Gaussian noise of known variance in two
// independent halves, with guides that carry the texture and the shadow (visibility).
#include "core/denoise/nfor_denoiser.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstring>
#include <random>

#include "core/film/image_error.h"
#include "core/denoise/firefly_guard.h"
#include "core/denoise/nl_means.h"

namespace penumbra {
namespace {

struct Synthetic {
    DenoiseInput input;
    Image truth, raw;
};

float albedo_at(int x, int y) { return ((x / 8 + y / 8) % 2) ? 0.8f : 0.2f; }
// Lit above the middle row, in a shadow a third as bright below it.
float light_at(int x, int y, int W, int H) {
    return (0.2f + 0.8f * float(x) / W) * (y < H / 2 ? 1.0f : 0.3f);
}

// sigma: the relative noise of one half's mean (plus a floor), as in a render.
Synthetic make_synthetic(int W, int H, float sigma, unsigned seed = 1) {
    std::mt19937 rng(seed);
    std::normal_distribution<float> N(0, 1);
    Synthetic s;
    DenoiseInput& in = s.input;
    s.truth = s.raw = Image(W, H, 3);
    in.color_a = in.color_b = in.color_variance = Image(W, H, 3);
    in.guide_a = in.guide_b = in.guide_variance = Image(W, H, kGuideChannels);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const float albedo = albedo_at(x, y);
            for (int c = 0; c < 3; ++c) {
                const float truth = albedo * light_at(x, y, W, H) * (c == 0 ? 1.0f : 0.7f);
                const float sd = sigma * (0.1f + truth);
                s.truth.at(x, y)[c] = truth;
                in.color_a.at(x, y)[c] = truth + sd * N(rng);
                in.color_b.at(x, y)[c] = truth + sd * N(rng);
                in.color_variance.at(x, y)[c] = sd * sd / 2;
                s.raw.at(x, y)[c] = 0.5f * (in.color_a.at(x, y)[c] + in.color_b.at(x, y)[c]);
            }
            const float visibility = y < H / 2 ? 1.0f : 0.0f;
            const float guide[kGuideChannels] = {albedo, albedo, albedo,        0,
                                                 0,      1,      5 + 0.01f * y, visibility};
            for (int c = 0; c < kGuideChannels; ++c) {
                in.guide_a.at(x, y)[c] = guide[c] + 0.01f * N(rng);
                in.guide_b.at(x, y)[c] = guide[c] + 0.01f * N(rng);
                in.guide_variance.at(x, y)[c] = 0.0001f / 2;
            }
        }
    return s;
}

TEST(Nfor, BeatsTheRawImageByAnOrderOfMagnitude) {
    for (float sigma : {0.3f, 1.0f}) {
        const Synthetic s = make_synthetic(128, 128, sigma);
        const DenoiseResult r = denoise_nfor(s.input);
        const double raw = relative_mse(s.raw, s.truth), denoised = relative_mse(r.color, s.truth);
        EXPECT_LT(denoised, raw / 10) << "sigma " << sigma;  // measured: 26x at 0.3, 51x at 1
    }
}

// The estimate has noise of its own: the squared differences it averages carry a raw
// half's variance, so its standard deviation is about the raw relMSE times sqrt(2 / M)
// over M pixel channels. At a half's noise of 100% that is 30% of the denoised error on
// a 128 x 128 image (estimate / truth over 8 noise seeds: 0.21-1.67) and 15% on 256 x 256
// (0.76-1.39), which this test uses.
TEST(Nfor, ErrorEstimateWithinAFactorOfTwo) {
    for (float sigma : {0.1f, 0.3f, 1.0f}) {
        const int size = sigma < 1 ? 128 : 256;
        const Synthetic s = make_synthetic(size, size, sigma, 7);
        const DenoiseResult r = denoise_nfor(s.input);
        const double truth = relative_mse(r.color, s.truth);
        EXPECT_GT(r.relmse_estimate, truth / 2) << "sigma " << sigma;
        EXPECT_LT(r.relmse_estimate, truth * 2) << "sigma " << sigma;
    }
}

// A converged image: the change is below the image's own noise (the variance of its
// mean, averaged), and no further from the truth than the input.
TEST(Nfor, ConvergedImageChangesLessThanItsNoise) {
    const Synthetic s = make_synthetic(96, 96, 0.003f);
    const DenoiseResult r = denoise_nfor(s.input);
    double noise = 0;
    for (float v : s.input.color_variance.pixels) noise += v;
    noise /= double(s.input.color_variance.pixels.size());
    EXPECT_LT(mean_squared_error(r.color, s.raw), noise);
    EXPECT_LE(mean_squared_error(r.color, s.truth), mean_squared_error(s.raw, s.truth));
}

// The checker's albedo edges and the shadow's edge keep their contrast at a half's noise
// of 30%: across each, the step between the two pixels either side is within 15% of the
// true one. The texture is in the albedo guide, the shadow in the visibility guide; but
// the colour is their product (albedo x light x visibility), which a fit linear in each
// follows only approximately where its window straddles both edges: it keeps 90% of the
// shadow's step (0.898-0.905 over the guide prefilter's settings), and without the
// visibility guide 65%.
TEST(Nfor, KeepsTextureAndHardShadowEdges) {
    const int W = 128, H = 128;
    auto mean_step = [&](const Image& img, bool shadow) {
        double step = 0;
        int n = 0;
        if (shadow) {
            for (int x = 0; x < W; ++x, ++n) step += img.at(x, H / 2 - 1)[0] - img.at(x, H / 2)[0];
        } else {  // the vertical checker edges at x = 8 i, in the lit half
            for (int y = 4; y < H / 2 - 4; ++y)
                for (int x = 8; x < W; x += 8, ++n)
                    step += std::abs(img.at(x, y)[0] - img.at(x - 1, y)[0]);
        }
        return step / n;
    };
    for (bool shadow : {false, true}) {
        const Synthetic s = make_synthetic(W, H, 0.3f);
        const Image out = denoise_nfor(s.input).color;
        const double truth = mean_step(s.truth, shadow), kept = mean_step(out, shadow);
        EXPECT_GT(kept, 0.85 * truth) << (shadow ? "shadow" : "texture");
        EXPECT_LT(kept, 1.15 * truth) << (shadow ? "shadow" : "texture");
    }
}

TEST(Nfor, SameBitsForAnyThreadCount) {
    const Synthetic s = make_synthetic(80, 70, 0.5f);
    Image one, two;
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        one = denoise_nfor(s.input).color;
    }
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
        two = denoise_nfor(s.input).color;
    }
    ASSERT_EQ(one.pixels.size(), two.pixels.size());
    EXPECT_EQ(0, std::memcmp(one.pixels.data(), two.pixels.data(), one.pixels.size() * 4));
}

// A single sample 2000 times the pixel's mean in one half: the denoised image does not
// spread it into a blotch. Around it, the error grows by less than 5 times the pixel's
// value (left in the mean, the spike alone would add 1000 times).
TEST(Nfor, AFireflyDoesNotBecomeABlotch) {
    const int fx = 40, fy = 20;
    const Synthetic clean = make_synthetic(96, 96, 0.1f);
    Synthetic s = clean;
    const float value = s.truth.at(fx, fy)[0], spike = 2000 * value;
    for (int c = 0; c < 3; ++c) {
        s.input.color_a.at(fx, fy)[c] += spike;
        // The pixel's sample variance holds the firefly too.
        s.input.color_variance.at(fx, fy)[c] += spike * spike / 4;
    }
    auto error_around = [&](const Image& img) {
        double e = 0;
        for (int y = fy - 10; y <= fy + 10; ++y)
            for (int x = fx - 10; x <= fx + 10; ++x)
                e += std::abs(img.at(x, y)[0] - s.truth.at(x, y)[0]);
        return e;
    };
    const DenoiseResult with = denoise_nfor(s.input);
    EXPECT_GE(with.fireflies, 1u);
    EXPECT_LT(error_around(with.color), error_around(denoise_nfor(clean.input).color) + 5 * value);
}

TEST(FireflyGuard, HoldsBackALoneSpikeAndKeepsWhatBothHalvesShow) {
    Planes a(9, 9, 3, 1.0f), b(9, 9, 3, 1.0f), var(9, 9, 3, 0.01f);
    for (int c = 0; c < 3; ++c) {
        a.at(c, 2, 2) = 500;  // in one half only: a firefly
        a.at(c, 6, 6) = 50;   // in both: a small bright feature
        b.at(c, 6, 6) = 45;
    }
    // The image's mean level (both halves) is above the firefly's surroundings (1).
    const float level = (2 * 81 - 3 + 500 + 50 + 45) / 162.0f;
    EXPECT_EQ(1u, guard_fireflies(a, b, var));
    EXPECT_FLOAT_EQ(kFireflyRatio * level, a.at(0, 2, 2));
    EXPECT_FLOAT_EQ(50, a.at(0, 6, 6));
    EXPECT_FLOAT_EQ(1, a.at(0, 3, 3));
    const float d = kFireflyRatio * level - 1;
    EXPECT_FLOAT_EQ(d * d / 4, var.at(0, 2, 2));
}

// Where caustics make fireflies dense, neighbours do not shield each other.
TEST(FireflyGuard, HoldsBackFirefliesSideBySide) {
    Planes a(32, 32, 3, 1.0f), b(32, 32, 3, 1.0f), var(32, 32, 3, 0.01f);
    for (int c = 0; c < 3; ++c) {
        a.at(c, 10, 10) = a.at(c, 11, 10) = 300;
        b.at(c, 10, 11) = 300;
    }
    EXPECT_EQ(3u, guard_fireflies(a, b, var));
    EXPECT_LT(a.at(0, 11, 10), 10);
    EXPECT_LT(b.at(0, 10, 11), 10);
}

// exp_neg's error: the series' truncation (1.1e-7 relative), the rounding of t = x log2(e)
// to float (2^-24 relative, so x 6e-8 absolute in the exponent and ln 2 x that in the
// result) and about ten roundings of the rest (6e-8 each).
TEST(NlMeans, ExpNegMatchesExp) {
    for (float x = 0; x < 80; x += 0.001953125f) {
        const double e = std::exp(-double(x));
        const double bound = 1.1e-7 + 0.7 * 6e-8 * x * 1.45 + 10 * 6e-8;
        ASSERT_NEAR(exp_neg(x), e, bound * e) << x;
    }
    EXPECT_EQ(1.0f, exp_neg(0));
    EXPECT_LT(exp_neg(std::nanf("")), 1e-37f);
}

}  // namespace
}  // namespace penumbra
