// The film's denoising buffers: the colour's and the guides' means over the even and the
// odd sample indices, and the variances of the full means, on samples fed by hand.
#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "core/film/film.h"
#include "job/aov_list.h"

namespace penumbra {
namespace {

AovRecord sample(bool odd, Spectrum albedo, Vec3 normal, float depth) {
    AovRecord r;
    r.odd = odd;
    r.guide = {albedo, normal, depth};
    return r;
}

AovRecord escaped(bool odd) {
    AovRecord r;
    r.odd = odd;
    return r;
}

float guide(const Image& img, int x, int channel) { return img.at(x, 0)[channel]; }

TEST(FilmDenoise, IsAnInternalSetThatSplitsTheSamples) {
    EXPECT_THROW(parse_aovs("denoise"), std::invalid_argument);
    EXPECT_FALSE(parse_aovs("all").has(Aov::Denoise));
    EXPECT_TRUE(AovSet{Aov::Denoise}.splits_halves());
    EXPECT_TRUE(AovSet{Aov::Error}.splits_halves());
    EXPECT_FALSE(parse_aovs("all").splits_halves());
    EXPECT_FALSE(AovSet{Aov::Denoise}.needs_first_hit());
    // Its buffers are listed, so checkpoints keep them.
    Film film(2, 1, {Aov::Denoise});
    film.add_sample(0, 0, {1, 1, 1}, 1, sample(false, {1, 1, 1}, {0, 0, 1}, 1));
    size_t guide_bytes = 0;
    for (const Film::Buffer& b : film.buffers())
        if (std::string(b.name).rfind("guide", 0) == 0) guide_bytes += b.bytes;
    EXPECT_EQ(guide_bytes, 3 * 2 * kGuideChannels * sizeof(double));
}

TEST(FilmDenoise, HalvesAndVariancesOfEqualWeights) {
    Film film(2, 1, {Aov::Denoise});
    // Pixel 0: red 1, 3 (even) and 5, 7 (odd); green 2 throughout; the last one escaped.
    film.add_sample(0, 0, {1, 2, 0}, 1, sample(false, {0.5f, 0, 0}, {0, 0, 1}, 2));
    film.add_sample(0, 0, {3, 2, 0}, 1, sample(false, {0.25f, 0, 0}, {0, 1, 0}, 4));
    film.add_sample(0, 0, {5, 2, 0}, 1, sample(true, {1, 0, 0}, {0, 0, -1}, 6));
    film.add_sample(0, 0, {7, 2, 0}, 1, escaped(true));
    // Pixel 1: one even sample and a NaN, dropped from the colour and the guides alike.
    film.add_sample(1, 0, {4, 4, 4}, 1, sample(false, {0.5f, 0.5f, 0.5f}, {1, 0, 0}, 3));
    film.add_sample(1, 0, {std::numeric_limits<float>::quiet_NaN(), 0, 0}, 1,
                    sample(true, {1, 1, 1}, {0, 1, 0}, 9));

    const DenoiseInput in = film.denoise_input();
    ASSERT_EQ(in.width(), 2);
    ASSERT_EQ(in.height(), 1);
    ASSERT_EQ(in.color_a.channels, 3);
    ASSERT_EQ(in.guide_a.channels, kGuideChannels);
    EXPECT_EQ(in.color_a.at(0, 0)[0], 2.0f);
    EXPECT_EQ(in.color_b.at(0, 0)[0], 6.0f);
    EXPECT_EQ(in.color_a.at(0, 0)[1], 2.0f);
    EXPECT_EQ(in.color_b.at(0, 0)[1], 2.0f);
    // Red: s^2 = 20 / 3 over n = 4; green has none.
    EXPECT_FLOAT_EQ(in.color_variance.at(0, 0)[0], 5.0f / 3);
    EXPECT_EQ(in.color_variance.at(0, 0)[1], 0.0f);

    EXPECT_EQ(guide(in.guide_a, 0, kGuideAlbedo), 0.375f);
    EXPECT_EQ(guide(in.guide_b, 0, kGuideAlbedo), 0.5f);  // the escaped sample counts as 0
    EXPECT_EQ(guide(in.guide_a, 0, kGuideNormal + 1), 0.5f);
    EXPECT_EQ(guide(in.guide_a, 0, kGuideNormal + 2), 0.5f);
    EXPECT_EQ(guide(in.guide_b, 0, kGuideNormal + 2), -0.5f);
    EXPECT_EQ(guide(in.guide_a, 0, kGuideDepth), 3.0f);
    EXPECT_EQ(guide(in.guide_b, 0, kGuideDepth), 3.0f);
    // Albedo R: 0.5, 0.25, 1, 0, mean 0.4375; depth 2, 4, 6, 0, mean 3.
    const double albedo_var = ((0.25 + 0.0625 + 1.0) / 4 - 0.4375 * 0.4375) / 3;
    EXPECT_FLOAT_EQ(guide(in.guide_variance, 0, kGuideAlbedo), float(albedo_var));
    EXPECT_FLOAT_EQ(guide(in.guide_variance, 0, kGuideDepth), 5.0f / 3);
    EXPECT_EQ(guide(in.guide_variance, 0, kGuideAlbedo + 1), 0.0f);

    // Pixel 1: the odd half is empty (0), and one sample has no variance.
    EXPECT_EQ(in.color_a.at(1, 0)[0], 4.0f);
    EXPECT_EQ(in.color_b.at(1, 0)[0], 0.0f);
    EXPECT_EQ(in.color_variance.at(1, 0)[0], 0.0f);
    EXPECT_EQ(guide(in.guide_a, 1, kGuideNormal), 1.0f);
    EXPECT_EQ(guide(in.guide_b, 1, kGuideDepth), 0.0f);
    EXPECT_EQ(guide(in.guide_variance, 1, kGuideDepth), 0.0f);
}

TEST(FilmDenoise, HalvesUseTheFilterWeights) {
    Film film(1, 1, {Aov::Denoise});
    film.add_sample(0, 0, Spectrum(1), 1, sample(false, {}, {}, 1));
    film.add_sample(0, 0, Spectrum(3), 3, sample(false, {}, {}, 3));
    film.add_sample(0, 0, Spectrum(4), 2, sample(true, {}, {}, 4));
    const DenoiseInput in = film.denoise_input();
    EXPECT_EQ(in.color_a.at(0, 0)[2], 2.5f);
    EXPECT_EQ(in.color_b.at(0, 0)[2], 4.0f);
    EXPECT_EQ(guide(in.guide_a, 0, kGuideDepth), 2.5f);
    EXPECT_EQ(guide(in.guide_b, 0, kGuideDepth), 4.0f);
    // Mean 18 / 6, weighted variance 60 / 6 - 3^2, n_eff = 6^2 / 14.
    const double mean = 18.0 / 6, var = (1 + 27 + 32) / 6.0 - mean * mean;
    EXPECT_FLOAT_EQ(in.color_variance.at(0, 0)[0], float(var / (36.0 / 14 - 1)));
    EXPECT_EQ(guide(in.guide_variance, 0, kGuideDepth), in.color_variance.at(0, 0)[0]);
}

TEST(FilmDenoise, ColourVarianceIsTheVarianceAov) {
    const AovSet aovs = {Aov::Denoise, Aov::Variance};
    Film film(5, 3, aovs);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 2.0f);
    for (int i = 0; i < 200; ++i) {
        AovRecord r = sample(i % 2 == 1, {u(rng), u(rng), u(rng)}, {0, 0, 1}, u(rng));
        film.add_sample(int(rng() % 5), int(rng() % 3), {u(rng), u(rng), u(rng)}, u(rng), r);
    }
    const Image variance = film.resolve_aov(Aov::Variance);
    const DenoiseInput in = film.denoise_input();
    ASSERT_EQ(variance.pixels.size(), in.color_variance.pixels.size());
    EXPECT_EQ(std::memcmp(variance.pixels.data(), in.color_variance.pixels.data(),
                          variance.pixels.size() * sizeof(float)),
              0);
    // The halves' means, weighted by their weights, give the beauty.
    const Image beauty = film.resolve();
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x) {
            const float a = in.color_a.at(x, y)[0], b = in.color_b.at(x, y)[0];
            EXPECT_GE(beauty.at(x, y)[0], std::min(a, b) - 1e-5f);
            EXPECT_LE(beauty.at(x, y)[0], std::max(a, b) + 1e-5f);
        }
}

}  // namespace
}  // namespace penumbra
