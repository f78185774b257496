// Film AOVs: parsing the list, first-hit averages (misses count as zero for albedo and
// normal, not at all for depth and position), sample counts and the variance of the mean.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/film/film.h"
#include "job/aov_list.h"

namespace penumbra {
namespace {

AovRecord hit(Spectrum albedo, Vec3 n, Vec3 p, float depth) {
    AovRecord r;
    r.hit = true;
    r.albedo = albedo;
    r.normal = n;
    r.position = p;
    r.depth = depth;
    return r;
}

TEST(FilmAov, ParsesTheList) {
    const AovSet s = parse_aovs("albedo, depth,samples");
    EXPECT_TRUE(s.has(Aov::Albedo));
    EXPECT_TRUE(s.has(Aov::Depth));
    EXPECT_TRUE(s.has(Aov::Samples));
    EXPECT_FALSE(s.has(Aov::Normal));
    EXPECT_TRUE(s.needs_first_hit());
    EXPECT_FALSE(parse_aovs("variance,samples").needs_first_hit());
    EXPECT_FALSE(parse_aovs("").any());
    const AovSet all = parse_aovs("all");
    for (Aov a : {Aov::Albedo, Aov::Normal, Aov::Depth, Aov::Position, Aov::Variance, Aov::Samples,
                  Aov::ObjectId, Aov::MaterialId, Aov::Vector})
        EXPECT_TRUE(all.has(a));
    EXPECT_TRUE(parse_aovs("vector").needs_first_hit());
    EXPECT_FALSE(all.has(Aov::Denoise));
    EXPECT_FALSE(all.has(Aov::Coverage));
    EXPECT_THROW(parse_aovs("albedo,emission"), std::invalid_argument);
}

TEST(FilmAov, FirstHitAveragesUseTheFilterWeights) {
    Film film(2, 1, parse_aovs("all"));
    // Pixel 0: two hits (weights 1 and 3) and a miss (weight 4).
    film.add_sample(0, 0, {1, 1, 1}, 1, hit({0.2f, 0.4f, 0.6f}, {0, 0, 1}, {1, 2, 3}, 2));
    film.add_sample(0, 0, {1, 1, 1}, 3, hit({0.6f, 0.4f, 0.2f}, {0, 1, 0}, {3, 2, 1}, 6));
    film.add_sample(0, 0, {1, 1, 1}, 4, AovRecord{});
    const Image albedo = film.resolve_aov(Aov::Albedo), normal = film.resolve_aov(Aov::Normal),
                depth = film.resolve_aov(Aov::Depth), pos = film.resolve_aov(Aov::Position),
                samples = film.resolve_aov(Aov::Samples);
    ASSERT_EQ(albedo.channels, 3);
    ASSERT_EQ(depth.channels, 1);
    EXPECT_FLOAT_EQ(albedo.at(0, 0)[0], (0.2f * 1 + 0.6f * 3) / 8);
    EXPECT_FLOAT_EQ(albedo.at(0, 0)[2], (0.6f * 1 + 0.2f * 3) / 8);
    EXPECT_FLOAT_EQ(normal.at(0, 0)[1], 3.0f / 8);
    EXPECT_FLOAT_EQ(normal.at(0, 0)[2], 1.0f / 8);
    EXPECT_FLOAT_EQ(depth.at(0, 0)[0], (2.0f * 1 + 6 * 3) / 4);  // hits only
    EXPECT_FLOAT_EQ(pos.at(0, 0)[0], (1.0f + 9) / 4);
    EXPECT_EQ(samples.at(0, 0)[0], 3);
    // Pixel 1: nothing was hit (and nothing sampled).
    EXPECT_EQ(depth.at(1, 0)[0], Film::kNoHitDepth);
    EXPECT_EQ(albedo.at(1, 0)[0], 0);
    EXPECT_EQ(samples.at(1, 0)[0], 0);
}

TEST(FilmAov, VectorsAverageOverTheHitsAsDepthDoes) {
    Film film(2, 1, parse_aovs("vector"));
    AovRecord a = hit({}, {}, {}, 1), b = hit({}, {}, {}, 1);
    a.motion = {1, -2, 3, -4};
    b.motion = {5, 6, -7, 8};
    // Pixel 0: two hits (weights 1 and 3) and a miss (weight 4), which counts for nothing.
    film.add_sample(0, 0, {1, 1, 1}, 1, a);
    film.add_sample(0, 0, {1, 1, 1}, 3, b);
    AovRecord miss;
    miss.motion = {100, 100, 100, 100};
    film.add_sample(0, 0, {1, 1, 1}, 4, miss);
    film.add_sample(1, 0, {1, 1, 1}, 1, miss);
    const Image v = film.resolve_aov(Aov::Vector);
    ASSERT_EQ(v.channels, 4);
    const float expected[4] = {(1 + 15) / 4.0f, (-2 + 18) / 4.0f, (3 - 21) / 4.0f,
                               (-4 + 24) / 4.0f};
    for (int c = 0; c < 4; ++c) EXPECT_FLOAT_EQ(v.at(0, 0)[c], expected[c]) << c;
    // Pixel 1: no sample hit, no vector.
    for (int c = 0; c < 4; ++c) EXPECT_EQ(v.at(1, 0)[c], 0.0f) << c;
}

TEST(FilmAov, VarianceIsThatOfTheMean) {
    Film film(3, 1, parse_aovs("variance,samples"));
    // Equal weights: the unbiased sample variance over n.
    const float v[] = {1, 2, 4, 9};
    for (float x : v) film.add_sample(0, 0, {x, 2 * x, 0}, 0.5f, AovRecord{});
    // Unequal weights, with one sample dropped as non-finite.
    film.add_sample(1, 0, {1, 0, 0}, 1, AovRecord{});
    film.add_sample(1, 0, {3, 0, 0}, 3, AovRecord{});
    film.add_sample(1, 0, {std::numeric_limits<float>::quiet_NaN(), 0, 0}, 2, AovRecord{});
    // A single sample says nothing about its variance.
    film.add_sample(2, 0, {5, 5, 5}, 1, AovRecord{});
    const Image var = film.resolve_aov(Aov::Variance);
    const double mean = 4, s2 = ((1 - mean) * (1 - mean) + 4 + 0 + 25) / 3;
    EXPECT_NEAR(var.at(0, 0)[0], s2 / 4, 1e-6);
    EXPECT_NEAR(var.at(0, 0)[1], 4 * s2 / 4, 1e-5);
    EXPECT_EQ(var.at(0, 0)[2], 0);
    // Weighted: mean 2.5, population variance 0.75, n_eff = 16 / 10.
    EXPECT_NEAR(var.at(1, 0)[0], 0.75 / (1.6 - 1), 1e-6);
    EXPECT_EQ(var.at(2, 0)[0], 0);
    EXPECT_EQ(film.resolve_aov(Aov::Samples).at(1, 0)[0], 3);  // all samples taken
    // The beauty is unaffected by the AOV bookkeeping.
    EXPECT_FLOAT_EQ(film.resolve().at(1, 0)[0], 2.5f);
}

TEST(FilmAov, AovsNotAskedForAreBlank) {
    Film film(1, 1, parse_aovs("depth"));
    film.add_sample(0, 0, {1, 1, 1}, 1, hit({1, 1, 1}, {0, 0, 1}, {0, 0, 0}, 3));
    EXPECT_FLOAT_EQ(film.resolve_aov(Aov::Depth).at(0, 0)[0], 3);
    EXPECT_EQ(film.resolve_aov(Aov::Albedo).at(0, 0)[0], 0);
}

TEST(FilmAov, ErrorEstimateComesFromTheTwoHalves) {
    Film film(2, 1, parse_aovs("error"));
    EXPECT_FALSE(parse_aovs("all").has(Aov::Error));  // it changes the sample streams
    // Pixel 0: even samples 1 and 3 (weights 1, 1), one odd sample 4 (weight 2): the
    // halves' means are A = 2 and B = 4, their weights nA = nB = 2.
    auto add = [&](int x, float v, float w, bool odd) {
        AovRecord r;
        r.odd = odd;
        film.add_sample(x, 0, Spectrum(v, 2 * v, 0), w, r);
    };
    add(0, 1, 1, false);
    add(0, 3, 1, false);
    add(0, 4, 2, true);
    // (A - B)^2 nA nB / (nA + nB)^2 = 4 * 4 / 16 = 1; the green channel 4 times that.
    EXPECT_NEAR(film.estimated_variance(0, 0).x, 1.0, 1e-6);
    EXPECT_NEAR(film.estimated_variance(0, 0).y, 4.0, 1e-6);
    EXPECT_EQ(film.estimated_variance(0, 0).z, 0.0f);
    // mean (3, 6, 0): sqrt((1 / 9.01 + 4 / 36.01 + 0) / 3).
    EXPECT_NEAR(film.relative_error(0, 0), std::sqrt((1 / 9.01 + 4 / 36.01) / 3), 1e-6);
    EXPECT_NEAR(film.resolve_aov(Aov::Error).at(0, 0)[0], film.relative_error(0, 0), 1e-7);
    // Pixel 1: only even samples: no estimate (0), whatever their spread.
    add(1, 1, 1, false);
    add(1, 5, 1, false);
    EXPECT_EQ(film.estimated_variance(1, 0).x, 0.0f);
    // Unequal halves: nA = 3 (one sample of weight 3, value 1), nB = 1 (value 5):
    // (4)^2 * 3 * 1 / 16 = 3.
    Film f2(1, 1, parse_aovs("error"));
    AovRecord even, odd;
    odd.odd = true;
    f2.add_sample(0, 0, Spectrum(1), 3, even);
    f2.add_sample(0, 0, Spectrum(5), 1, odd);
    EXPECT_NEAR(f2.estimated_variance(0, 0).x, 3.0, 1e-6);
}

}  // namespace
}  // namespace penumbra
