#include "core/sampling/zsobol_sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "core/error.h"
#include "tests/support/statistics/chi2.h"
#include "tests/support/statistics/sampler_checks.h"

namespace penumbra {
namespace {

int log2_of(uint32_t n) {
    int m = 0;
    while ((1u << m) < n) ++m;
    return m;
}

// True when every elementary interval of area 1/n (n = 2^m) holds exactly one point.
bool is_zero_m_two_net(const std::vector<Vec2>& pts, std::string* why) {
    const int m = log2_of(uint32_t(pts.size()));
    for (int a = 0; a <= m; ++a) {
        const int nx = 1 << a, ny = 1 << (m - a);
        std::set<int> cells;
        for (const Vec2& p : pts) cells.insert(int(p.x * nx) * ny + int(p.y * ny));
        if (cells.size() != pts.size()) {
            *why = std::to_string(nx) + "x" + std::to_string(ny) +
                   " intervals: " + std::to_string(cells.size()) + " of " +
                   std::to_string(pts.size());
            return false;
        }
    }
    return true;
}

TEST(ZSobolSampler, FastSecondDimensionMatchesTheGeneratorMatrix) {
    for (uint32_t i = 0; i < 4096; ++i)
        ASSERT_EQ(sobol_second_dimension_reversed(i),
                  van_der_corput_bits(sobol_second_dimension_bits(i)))
            << i;
    for (uint32_t i : {0xffffffffu, 0x80000001u, 0x12345678u, 0xdeadbeefu})
        EXPECT_EQ(sobol_second_dimension_reversed(i),
                  van_der_corput_bits(sobol_second_dimension_bits(i)));
}

TEST(ZSobolSampler, OwenHashKeepsDyadicIntervalsTogether) {
    // Bit-reversed, low bits are the fraction's leading digits: values that share their
    // low m bits must still share them after the hash, and no others may.
    for (uint32_t seed : {0u, 0x9e3779b9u, 0xffffffffu})
        for (uint32_t a = 0; a < 64; ++a)
            for (uint32_t b = 0; b < 64; ++b) {
                const uint32_t va = a | 12345u << 6, vb = b | 999u << 6;
                const uint32_t sa = owen_hash_reversed(va, seed), sb = owen_hash_reversed(vb, seed);
                for (int m = 1; m <= 6; ++m) {
                    const uint32_t mask = (1u << m) - 1;
                    ASSERT_EQ((va & mask) == (vb & mask), (sa & mask) == (sb & mask));
                }
            }
}

TEST(ZSobolSampler, MortonCodeInterleavesBits) {
    EXPECT_EQ(morton_2d(0, 0), 0u);
    EXPECT_EQ(morton_2d(1, 0), 1u);
    EXPECT_EQ(morton_2d(0, 1), 2u);
    EXPECT_EQ(morton_2d(3, 3), 15u);
    EXPECT_EQ(morton_2d(0xffff, 0), 0x55555555u);
    EXPECT_EQ(morton_2d(0, 0xffff), 0xaaaaaaaau);
}

// The digit shuffle is a bijection on each pixel's block of indices, whatever the spp
// (odd powers of two end in a base-2 digit).
TEST(ZSobolSampler, EachPixelTakesOneAlignedBlockOfTheSequence) {
    for (uint32_t spp : {1u, 2u, 8u, 16u, 32u, 12u}) {
        const int m = log2_of(spp);
        ZSobolSampler s(spp, 11);
        for (PixelCoord p : {PixelCoord{0, 0}, PixelCoord{5, 9}, PixelCoord{1000, 77}})
            for (uint32_t dim : {0u, 1u, 6u}) {
                std::set<uint64_t> blocks, indices;
                for (uint32_t i = 0; i < (1u << m); ++i) {
                    s.start_pixel_sample(p, i);
                    const uint64_t index = s.sobol_index(dim);
                    blocks.insert(index >> m);
                    indices.insert(index);
                }
                EXPECT_EQ(blocks.size(), 1u) << "spp " << spp << " dim " << dim;
                EXPECT_EQ(indices.size(), size_t(1) << m) << "spp " << spp << " dim " << dim;
            }
    }
}

// Pixels below 256 x 256 take cached shortcuts (the shuffled top digits, the pixel's
// digits per dimension); those above do not. Together, 512 x 512 pixels at 1 spp must
// still take distinct indices that agree above bit 18: one bijection over the quadtree.
TEST(ZSobolSampler, CachedAndDirectDigitsFormOneShuffle) {
    for (uint32_t dim : {0u, 5u, 63u, 64u}) {
        ZSobolSampler s(1, 21);
        std::vector<bool> seen(1u << 18, false);
        uint64_t top = 0;
        bool first = true;
        size_t distinct = 0;
        for (int y = 0; y < 512; ++y)
            for (int x = 0; x < 512; ++x) {
                s.start_pixel_sample({x, y}, 0);
                const uint64_t index = s.sobol_index(dim);
                if (first) top = index >> 18, first = false;
                ASSERT_EQ(index >> 18, top) << x << " " << y << " dim " << dim;
                distinct += !seen[index & 0x3ffff];
                seen[index & 0x3ffff] = true;
            }
        EXPECT_EQ(distinct, size_t(1) << 18) << "dim " << dim;
    }
    // The cache only remembers: a fresh sampler and a warm one agree for every sample.
    ZSobolSampler warm(16, 4);
    for (uint32_t i = 0; i < 16; ++i)
        for (PixelCoord p : {PixelCoord{3, 4}, PixelCoord{300, 4}}) {
            ZSobolSampler cold(16, 4);
            warm.start_pixel_sample(p, i);
            cold.start_pixel_sample(p, i);
            for (uint32_t d : {7u, 0u, 70u}) EXPECT_EQ(warm.sobol_index(d), cold.sobol_index(d));
        }
}

// For power-of-two spp every 2D pair of a pixel's samples is a (0,m,2)-net, also for
// odd m; and a 2x2 quad of pixels together forms a (0,m+2,2)-net (the Z order).
TEST(ZSobolSampler, PixelsAndPixelQuadsFormZeroMTwoNets) {
    for (uint32_t spp : {4u, 16u, 32u, 64u}) {
        ZSobolSampler s(spp, 42);
        for (int quad = 0; quad < 4; ++quad)
            for (int pair = 0; pair < 4; ++pair) {
                std::vector<Vec2> quad_pts;
                for (int q = 0; q < 4; ++q) {
                    const PixelCoord p{2 * quad + 6 + (q & 1), 2 * (quad / 2) + 10 + (q >> 1)};
                    std::vector<Vec2> pts;
                    for (uint32_t i = 0; i < spp; ++i) {
                        s.start_pixel_sample(p, i);
                        for (int d = 0; d < pair; ++d) s.get_2d();
                        const Vec2 v = s.get_2d();
                        ASSERT_TRUE(v.x >= 0 && v.x < 1 && v.y >= 0 && v.y < 1);
                        pts.push_back(v);
                        quad_pts.push_back(v);
                    }
                    std::string why;
                    EXPECT_TRUE(is_zero_m_two_net(pts, &why))
                        << "spp " << spp << " pair " << pair << ": " << why;
                }
                std::string why;
                EXPECT_TRUE(is_zero_m_two_net(quad_pts, &why))
                    << "quad, spp " << spp << " pair " << pair << ": " << why;
            }
    }
}

TEST(ZSobolSampler, OneDimensionalValuesAreStratifiedPerPixel) {
    ZSobolSampler s(32, 7);
    for (int dim = 0; dim < 5; ++dim) {
        std::set<int> strata;
        for (uint32_t i = 0; i < 32; ++i) {
            s.start_pixel_sample({1, 2}, i);
            for (int d = 0; d < dim; ++d) s.get_1d();
            strata.insert(int(s.get_1d() * 32));
        }
        EXPECT_EQ(strata.size(), 32u) << "dimension " << dim;
    }
}

// The first 12 dimensions (mixing get_1d and get_2d) of 64x64 pixels at 16 spp.
std::vector<std::vector<float>> draw_dimensions(uint32_t spp, uint64_t seed) {
    ZSobolSampler s(spp, seed);
    std::vector<std::vector<float>> dims(12);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
            for (uint32_t i = 0; i < spp; ++i) {
                s.start_pixel_sample({x, y}, i);
                const Vec2 a = s.get_pixel_2d(), b = s.get_2d();
                const float c = s.get_1d();
                const Vec2 d = s.get_2d();
                const float e = s.get_1d(), f = s.get_1d();
                const Vec2 g = s.get_2d(), h = s.get_2d();
                const float v[12] = {a.x, a.y, b.x, b.y, c, d.x, d.y, e, f, g.x, g.y, h.x};
                for (int k = 0; k < 12; ++k) dims[k].push_back(v[k]);
            }
    return dims;
}

// Each dimension is uniform (64 bins, 65536 values: a density off by 10% over an eighth
// of [0,1) stands out at chi-square ~ 100 over 63 degrees of freedom), and every pair of
// dimensions from different draws is independent (8 x 8 bins).
TEST(ZSobolSampler, DimensionsAreUniformAndPairsIndependent) {
    const auto dims = draw_dimensions(16, 3);
    const size_t n = dims[0].size();
    const int tests = 12 + 12 * 11 / 2 - 4;  // same-draw pairs are nets, not tested
    const double significance = test::sidak_significance(0.01, tests);
    for (int k = 0; k < 12; ++k) {
        std::vector<double> observed(64, 0), expected(64, double(n) / 64);
        for (float v : dims[k]) observed[std::min(int(v * 64), 63)] += 1;
        const auto r = test::chi2_compare(observed, expected, n, significance,
                                          [](size_t c) { return std::to_string(c); });
        EXPECT_TRUE(r.passed) << "dimension " << k << ": " << r.report;
    }
    // Pairs drawn by one get_2d call: (0,1) (2,3) (5,6) (9,10).
    const std::set<std::pair<int, int>> same_draw = {{0, 1}, {2, 3}, {5, 6}, {9, 10}};
    int tested = 0;
    for (int a = 0; a < 12; ++a)
        for (int b = a + 1; b < 12; ++b) {
            if (same_draw.count({a, b})) continue;
            std::vector<double> observed(64, 0), expected(64, double(n) / 64);
            for (size_t i = 0; i < n; ++i)
                observed[std::min(int(dims[a][i] * 8), 7) * 8 + std::min(int(dims[b][i] * 8), 7)] +=
                    1;
            const auto r = test::chi2_compare(observed, expected, n, significance,
                                              [](size_t c) { return std::to_string(c); });
            EXPECT_TRUE(r.passed) << "dimensions " << a << ", " << b << ": " << r.report;
            ++tested;
        }
    EXPECT_EQ(tested + 12, tests);
}

TEST(ZSobolSampler, PrefixesOfTheBudgetAreUnbiased) {
    test::expect_unbiased_prefixes(
        [](uint64_t seed) { return std::make_unique<ZSobolSampler>(64, seed); });
}

TEST(ZSobolSampler, IndicesBeyondTheBudgetAreRejected) {
    ZSobolSampler s(12, 1);  // room for 16
    EXPECT_NO_THROW(s.start_pixel_sample({0, 0}, 15));
    EXPECT_THROW(s.start_pixel_sample({0, 0}, 16), InternalError);
}

TEST(ZSobolSampler, NeighbouringPixelsGetDifferentSamples) {
    ZSobolSampler s(16, 5);
    std::set<float> firsts;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            s.start_pixel_sample({x, y}, 0);
            firsts.insert(s.get_1d());
        }
    EXPECT_EQ(firsts.size(), 64u);
}

}  // namespace
}  // namespace penumbra
