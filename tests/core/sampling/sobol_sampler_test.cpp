#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "core/sampling/hash.h"
#include "core/sampling/sampler.h"

namespace penumbra {
namespace {

TEST(SobolSampler, SecondDimensionMatchesKnownSobolPoints) {
    // The first points of Sobol's second dimension in index (not Gray-code) order:
    // direction numbers 1/2, 3/4, 5/8, each the previous xor itself shifted right.
    const double expected[] = {0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875};
    for (uint32_t i = 0; i < 8; ++i)
        EXPECT_DOUBLE_EQ(sobol_second_dimension_bits(i) * 0x1p-32, expected[i]) << i;
    EXPECT_DOUBLE_EQ(van_der_corput_bits(3) * 0x1p-32, 0.75);
}

TEST(SobolSampler, OwenScrambleIsABijectionThatKeepsPrefixes) {
    // An Owen scramble maps each dyadic interval [k/2^m, (k+1)/2^m) onto another one:
    // values sharing their top m bits stay together.
    const uint32_t seed = 0x9e3779b9u;
    for (uint32_t a = 0; a < 64; ++a)
        for (uint32_t b = 0; b < 64; ++b) {
            const uint32_t va = a << 26 | 12345, vb = b << 26 | 999;
            const uint32_t sa = owen_scramble(va, seed), sb = owen_scramble(vb, seed);
            for (int m = 1; m <= 6; ++m) {
                const bool same_prefix = (va >> (32 - m)) == (vb >> (32 - m));
                EXPECT_EQ(same_prefix, (sa >> (32 - m)) == (sb >> (32 - m)));
            }
        }
}

TEST(SobolSampler, ValuesAreTheScrambledSequenceAsDefined) {
    // The sampler skips bit reversals that cancel; its values must stay those of the
    // definition: sample index permuted per (pixel, dimension), then the two (0,2)
    // dimensions Owen-scrambled with the dimension hash's halves.
    auto to_float = [](uint32_t v) { return std::min(v * 0x1p-32f, 0x1.fffffep-1f); };
    for (uint32_t spp : {16u, 12u}) {
        SobolSampler sampler(spp, 7);
        for (const PixelCoord p : {PixelCoord{0, 0}, PixelCoord{37, 5}})
            for (uint32_t i = 0; i < spp; ++i) {
                sampler.start_pixel_sample(p, i);
                for (uint32_t dim = 0; dim < 12; dim += 3) {
                    const uint64_t h1 = hash_values(7, p.x, p.y, dim, 0x50b01);
                    const uint32_t i1 = permutation_element(i, spp, uint32_t(h1));
                    EXPECT_EQ(sampler.get_1d(),
                              to_float(owen_scramble(van_der_corput_bits(i1), uint32_t(h1 >> 32))));
                    const uint64_t h2 = hash_values(7, p.x, p.y, dim + 1, 0x50b01);
                    const uint32_t i2 = permutation_element(i, spp, uint32_t(h2));
                    const Vec2 u = sampler.get_2d();
                    EXPECT_EQ(u.x, to_float(owen_scramble(van_der_corput_bits(i2),
                                                           uint32_t(h2 >> 32))));
                    EXPECT_EQ(u.y, to_float(owen_scramble(sobol_second_dimension_bits(i2),
                                                           uint32_t(mix_bits(h2)))));
                }
            }
    }
}

// For power-of-two spp, every 2D pair of a pixel's samples is a (0,m,2)-net: each
// elementary interval of area 1/spp holds exactly one point.
TEST(SobolSampler, PixelSamplesFormZeroMTwoNets) {
    for (uint32_t spp : {16u, 64u}) {
        int m = 0;
        while ((1u << m) < spp) ++m;
        SobolSampler sampler(spp, 42);
        for (int px = 0; px < 5; ++px)
            for (int dim_pair = 0; dim_pair < 3; ++dim_pair) {
                std::vector<Vec2> pts;
                for (uint32_t i = 0; i < spp; ++i) {
                    sampler.start_pixel_sample({px, 3}, i);
                    for (int d = 0; d < dim_pair; ++d) sampler.get_2d();
                    pts.push_back(sampler.get_2d());
                }
                for (int a = 0; a <= m; ++a) {
                    const int nx = 1 << a, ny = 1 << (m - a);
                    std::set<int> cells;
                    for (const Vec2& p : pts) {
                        ASSERT_GE(p.x, 0.0f);
                        ASSERT_LT(p.x, 1.0f);
                        cells.insert(int(p.x * nx) * ny + int(p.y * ny));
                    }
                    EXPECT_EQ(cells.size(), spp) << "spp " << spp << " pixel " << px
                                                 << " pair " << dim_pair << " intervals "
                                                 << nx << "x" << ny;
                }
            }
    }
}

TEST(SobolSampler, OneDimensionalSamplesAreStratified) {
    SobolSampler sampler(32, 7);
    std::set<int> strata;
    for (uint32_t i = 0; i < 32; ++i) {
        sampler.start_pixel_sample({1, 2}, i);
        sampler.get_2d();
        strata.insert(int(sampler.get_1d() * 32));
    }
    EXPECT_EQ(strata.size(), 32u);
}

TEST(SobolSampler, DependsOnlyOnSeedPixelAndIndex) {
    SobolSampler a(16, 5), b(16, 5), c(16, 6);
    a.start_pixel_sample({3, 4}, 7);
    const Vec2 first = a.get_2d();
    b.start_pixel_sample({9, 9}, 2);
    b.get_2d();
    b.start_pixel_sample({3, 4}, 7);
    const Vec2 again = b.get_2d();
    EXPECT_EQ(first.x, again.x);
    EXPECT_EQ(first.y, again.y);
    c.start_pixel_sample({3, 4}, 7);
    const Vec2 other = c.get_2d();
    EXPECT_TRUE(other.x != first.x || other.y != first.y);
    // Neighbouring pixels are decorrelated by their scrambles.
    a.start_pixel_sample({4, 4}, 7);
    const Vec2 next = a.get_2d();
    EXPECT_TRUE(next.x != first.x || next.y != first.y);
}

}  // namespace
}  // namespace penumbra
