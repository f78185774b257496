#include "core/sampling/tabled_sobol_sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "core/sampling/hash.h"
#include "core/sampling/path_sampler.h"
#include "tests/support/statistics/chi2.h"
#include "tests/support/statistics/sampler_checks.h"

namespace penumbra {
namespace {

int log2_of(uint32_t n) {
    int m = 0;
    while ((1u << m) < n) ++m;
    return m;
}

// Whether the points form a (0,m,2)-net: each elementary interval of area 1/n holds one.
bool is_zero_m_two_net(const std::vector<Vec2>& pts) {
    const int m = log2_of(uint32_t(pts.size()));
    for (int a = 0; a <= m; ++a) {
        const int nx = 1 << a, ny = 1 << (m - a);
        std::set<int> cells;
        for (const Vec2& p : pts) cells.insert(int(p.y * ny) * nx + int(p.x * nx));
        if (cells.size() != pts.size()) return false;
    }
    return true;
}

Vec2 entry_point(uint64_t w) {
    return {uint32_t(w) * 0x1p-32f, uint32_t(w >> 32) * 0x1p-32f};
}

TEST(TabledSobolSampler, TablesAreScrambledNetsInDifferentOrders) {
    for (uint32_t spp : {1u, 16u, 64u, 1024u, 65536u}) {
        const TabledSobolSampler s(spp, 9);
        const uint32_t tables = s.tables();
        EXPECT_EQ(tables, std::min(std::max(2048u / spp, 1u), std::min(64u, 65536u / spp)));
        std::set<std::vector<uint64_t>> distinct;
        for (uint32_t t = 0; t < tables; ++t) {
            std::vector<Vec2> pts;
            std::vector<uint64_t> entries;
            for (uint32_t e = 0; e < spp; ++e) {
                const uint64_t w = s.table_entry(t * spp + e);
                EXPECT_EQ(w & 0x000000ff000000ffull, 0u);
                pts.push_back(entry_point(w));
                entries.push_back(w);
            }
            EXPECT_TRUE(is_zero_m_two_net(pts)) << "spp " << spp << " table " << t;
            distinct.insert(entries);
        }
        EXPECT_EQ(distinct.size(), tables) << "spp " << spp;
    }
}

TEST(TabledSobolSampler, ValuesFollowTheDefinition) {
    const TabledSobolSampler prototype(64, 7);
    TabledSobolSampler s = prototype;
    const uint32_t mask = s.tables() * 64 - 1;
    for (const PixelCoord p : {PixelCoord{0, 0}, PixelCoord{37, 5}, PixelCoord{-3, 900}})
        for (uint32_t i : {0u, 5u, 63u}) {
            s.start_pixel_sample(p, i);
            for (uint32_t d = 0; d < 12; d += 3) {
                auto w = [&](uint32_t dim) {
                    const uint64_t h = mix_bits(hash_values(7, p.x, p.y) +
                                                dim * TabledSobolSampler::kGolden);
                    const uint32_t sel = uint32_t(h & 0xff) | uint32_t((h >> 32) & 0xff) << 8;
                    return s.table_entry((sel ^ i) & mask) ^ h;
                };
                const uint64_t w1 = w(d), w2 = w(d + 1);
                EXPECT_EQ(s.get_1d(), (uint32_t(w1) >> 8) * 0x1p-24f);
                const Vec2 u = s.get_2d();
                EXPECT_EQ(u.x, (uint32_t(w2) >> 8) * 0x1p-24f);
                EXPECT_EQ(u.y, (uint32_t(w2 >> 40)) * 0x1p-24f);
            }
        }
}

// Every 2D draw of a pixel's samples is a (0,m,2)-net, and every dimension has one
// sample per stratum of 1/spp.
TEST(TabledSobolSampler, PixelSamplesFormNetsAndStrata) {
    for (uint32_t spp : {2u, 16u, 64u, 1024u}) {
        TabledSobolSampler s(spp, 42);
        for (int px = 0; px < 6; ++px) {
            const int draws = 7;  // 2D, 1D, 2D, 1D, ...
            std::vector<std::vector<Vec2>> pts(draws);
            for (uint32_t i = 0; i < spp; ++i) {
                s.start_pixel_sample({px, 3 * px}, i);
                for (int d = 0; d < draws; ++d)
                    pts[d].push_back(d % 2 ? Vec2(s.get_1d(), 0.5f) : s.get_2d());
            }
            for (int d = 0; d < draws; ++d) {
                std::set<int> strata_x, strata_y;
                for (const Vec2& p : pts[d]) {
                    ASSERT_TRUE(p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1);
                    strata_x.insert(int(p.x * spp));
                    strata_y.insert(int(p.y * spp));
                }
                EXPECT_EQ(strata_x.size(), spp) << "spp " << spp << " draw " << d;
                if (d % 2 == 0) {
                    EXPECT_EQ(strata_y.size(), spp) << "spp " << spp << " draw " << d;
                    EXPECT_TRUE(is_zero_m_two_net(pts[d])) << "spp " << spp << " draw " << d;
                }
            }
        }
    }
}

// The first 12 dimensions (mixing get_1d and get_2d) of 64 x 64 pixels.
std::vector<std::vector<float>> draw_dimensions(uint32_t spp, uint64_t seed,
                                                uint32_t first = 0, uint32_t count = 0) {
    TabledSobolSampler s(spp, seed);
    std::vector<std::vector<float>> dims(12);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
            for (uint32_t i = first; i < (count ? first + count : spp); ++i) {
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

// Each dimension is uniform (64 bins; 65536 values at 16 spp, where a density off by 10%
// over an eighth of [0,1) stands out at chi-square ~ 100 over 63 degrees of freedom), and
// every pair of dimensions is uniform on [0,1)^2 (8 x 8 bins): those of different draws
// independent. The same with one sample index per pixel (4096 values), where nothing
// is stratified: each sample's values alone must be uniform and independent.
TEST(TabledSobolSampler, DimensionsAreUniformAndPairsIndependent) {
    for (const auto& [first, count] : {std::pair<uint32_t, uint32_t>{0, 0}, {5, 1}}) {
        const auto dims = draw_dimensions(16, 3, first, count);
        const size_t n = dims[0].size();
        const int tests = 12 + 12 * 11 / 2;
        const double significance = test::sidak_significance(0.01, 2 * tests);
        for (int k = 0; k < 12; ++k) {
            std::vector<double> observed(64, 0), expected(64, double(n) / 64);
            for (float v : dims[k]) observed[std::min(int(v * 64), 63)] += 1;
            const auto r = test::chi2_compare(observed, expected, n, significance,
                                              [](size_t c) { return std::to_string(c); });
            EXPECT_TRUE(r.passed) << "index " << first << ", dimension " << k << ": " << r.report;
        }
        for (int a = 0; a < 12; ++a)
            for (int b = a + 1; b < 12; ++b) {
                std::vector<double> observed(64, 0), expected(64, double(n) / 64);
                for (size_t i = 0; i < n; ++i)
                    observed[std::min(int(dims[a][i] * 8), 7) * 8 +
                             std::min(int(dims[b][i] * 8), 7)] += 1;
                const auto r = test::chi2_compare(observed, expected, n, significance,
                                                  [](size_t c) { return std::to_string(c); });
                EXPECT_TRUE(r.passed)
                    << "index " << first << ", dimensions " << a << ", " << b << ": " << r.report;
            }
    }
}

// Dimensions of different draws must not correlate within a pixel: per pixel, the
// estimate of P(u_a + u_b < 0.7) from 16 samples has at most independent sampling's
// variance p (1 - p) / 16 (stratifying each dimension lowers it; a shared index order
// would raise it for some pairs). 4096 pixels: the measured variance has a relative
// standard error of about 2.5%, so 1.1x stands 4 errors above the bound.
TEST(TabledSobolSampler, PairsOfDifferentDrawsDecorrelateWithinPixels) {
    const uint32_t spp = 16;
    const auto dims = draw_dimensions(spp, 11);
    const double p = 0.7 * 0.7 / 2, bound = p * (1 - p) / spp;
    const std::set<std::pair<int, int>> same_draw = {{0, 1}, {2, 3}, {5, 6}, {9, 10}};
    for (int a = 0; a < 12; ++a)
        for (int b = a + 1; b < 12; ++b) {
            if (same_draw.count({a, b})) continue;
            double sq = 0;
            const size_t pixels = dims[0].size() / spp;
            for (size_t px = 0; px < pixels; ++px) {
                int hits = 0;
                for (uint32_t i = 0; i < spp; ++i)
                    hits += dims[a][px * spp + i] + dims[b][px * spp + i] < 0.7f;
                sq += (hits / double(spp) - p) * (hits / double(spp) - p);
            }
            EXPECT_LT(sq / pixels, 1.1 * bound) << "dimensions " << a << ", " << b;
        }
}

TEST(TabledSobolSampler, PrefixesOfTheBudgetAreUnbiased) {
    test::expect_unbiased_prefixes(
        [](uint64_t seed) { return std::make_unique<TabledSobolSampler>(64, seed); });
}

// Skipping a dimension (a pinhole camera's lens sample) or deferring one (the light
// choice that a remapping light sampler does not read) leaves every value the same as
// drawing it: the images do not change with what is read.
TEST(TabledSobolSampler, SkippedAndDeferredDimensionsKeepTheOthers) {
    TabledSobolSampler drawn(64, 9), skipped(64, 9);
    for (uint32_t i = 0; i < 64; ++i) {
        drawn.start_pixel_sample({5, 11}, i);
        skipped.start_pixel_sample({5, 11}, i);
        const Vec2 a0 = drawn.get_2d(), b0 = skipped.get_2d();
        EXPECT_EQ(a0.x, b0.x);
        EXPECT_EQ(a0.y, b0.y);
        drawn.get_2d();
        skipped.skip_2d();
        const float a1 = drawn.get_1d();
        PathSampler path(skipped);
        const PathSampler::Deferred1d d = path.defer_1d();
        const Vec2 a2 = drawn.get_2d(), b2 = path.get_2d();
        EXPECT_EQ(a2.x, b2.x);
        EXPECT_EQ(a2.y, b2.y);
        EXPECT_EQ(a1, path.value(d));  // read after the draws that followed it
        EXPECT_EQ(drawn.get_1d(), skipped.get_1d());
    }
}

// Other samplers draw a skipped or deferred dimension as they would any other.
TEST(TabledSobolSampler, OtherSamplersDrawSkippedAndDeferredDimensions) {
    for (SamplerType type : {SamplerType::Stratified, SamplerType::Sobol, SamplerType::ZSobol,
                             SamplerType::Independent}) {
        SCOPED_TRACE(int(type));
        std::unique_ptr<Sampler> drawn = make_sampler(type, 16, 3);
        std::unique_ptr<Sampler> skipped = make_sampler(type, 16, 3);
        drawn->start_pixel_sample({2, 3}, 5);
        skipped->start_pixel_sample({2, 3}, 5);
        drawn->get_2d();
        skipped->skip_2d();
        const float a = drawn->get_1d();
        PathSampler path(*skipped);
        const PathSampler::Deferred1d d = path.defer_1d();
        const Vec2 a2 = drawn->get_2d(), b2 = path.get_2d();
        EXPECT_EQ(a2.x, b2.x);
        EXPECT_EQ(a2.y, b2.y);
        EXPECT_EQ(a, path.value(d));
    }
}

TEST(TabledSobolSampler, OtherCountsGetTheStratifiedSampler) {
    EXPECT_TRUE(tabled_sobol_supports(1));
    EXPECT_TRUE(tabled_sobol_supports(64));
    EXPECT_TRUE(tabled_sobol_supports(65536));
    EXPECT_FALSE(tabled_sobol_supports(0));
    EXPECT_FALSE(tabled_sobol_supports(12));
    EXPECT_FALSE(tabled_sobol_supports(1u << 17));
    EXPECT_NE(dynamic_cast<TabledSobolSampler*>(make_sampler(SamplerType::TabledSobol, 64, 1).get()),
              nullptr);
    EXPECT_NE(dynamic_cast<StratifiedSampler*>(make_sampler(SamplerType::TabledSobol, 12, 1).get()),
              nullptr);
}

}  // namespace
}  // namespace penumbra
