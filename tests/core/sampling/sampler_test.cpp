#include "core/sampling/sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace penumbra {
namespace {

// The dimensions every test draws, in this order, after start_pixel_sample: a mix of
// 1D and 2D requests like a path tracer's.
enum class Kind { D1, D2, Pixel };
const Kind kPattern[] = {Kind::Pixel, Kind::D1, Kind::D2, Kind::D1, Kind::D1, Kind::D2, Kind::D2};

std::vector<float> draw(Sampler& s, PixelCoord p, uint32_t index) {
    s.start_pixel_sample(p, index);
    std::vector<float> v;
    for (Kind k : kPattern) {
        if (k == Kind::D1) {
            v.push_back(s.get_1d());
        } else {
            const Vec2 u = k == Kind::Pixel ? s.get_pixel_2d() : s.get_2d();
            v.push_back(u.x);
            v.push_back(u.y);
        }
    }
    return v;
}

TEST(StratifiedSampler, OneSamplePerStratumInEveryDimension) {
    for (uint32_t spp : {16u, 12u, 7u}) {
        StratifiedSampler s(spp, 42);
        const uint32_t nx = s.strata_x(), ny = s.strata_y();
        ASSERT_EQ(nx * ny, spp);
        for (PixelCoord p : {PixelCoord{0, 0}, PixelCoord{17, 3}, PixelCoord{-2, 1000}}) {
            std::vector<std::vector<float>> rows;
            for (uint32_t i = 0; i < spp; ++i) rows.push_back(draw(s, p, i));
            size_t col = 0;
            for (Kind k : kPattern) {
                std::vector<int> hits(spp, 0);
                for (const auto& row : rows) {
                    if (k == Kind::D1) {
                        const float v = row[col];
                        ASSERT_GE(v, 0.0f);
                        ASSERT_LT(v, 1.0f);
                        ++hits[static_cast<uint32_t>(v * spp)];
                    } else {
                        const float x = row[col], y = row[col + 1];
                        ASSERT_TRUE(x >= 0 && x < 1 && y >= 0 && y < 1) << x << " " << y;
                        ++hits[static_cast<uint32_t>(y * ny) * nx + static_cast<uint32_t>(x * nx)];
                    }
                }
                for (uint32_t h = 0; h < spp; ++h)
                    EXPECT_EQ(hits[h], 1) << "spp " << spp << " column " << col << " stratum " << h;
                col += k == Kind::D1 ? 1 : 2;
            }
        }
    }
}

TEST(StratifiedSampler, SquarestFactorization) {
    EXPECT_EQ(StratifiedSampler(16, 1).strata_x(), 4u);
    EXPECT_EQ(StratifiedSampler(12, 1).strata_x(), 3u);
    EXPECT_EQ(StratifiedSampler(12, 1).strata_y(), 4u);
    EXPECT_EQ(StratifiedSampler(7, 1).strata_x(), 1u);
    EXPECT_EQ(StratifiedSampler(1, 1).strata_y(), 1u);
}

class SamplerTypes : public ::testing::TestWithParam<SamplerType> {};

TEST_P(SamplerTypes, ValuesArePureFunctionsOfSeedPixelAndIndex) {
    auto s = make_sampler(GetParam(), 16, 7);
    const PixelCoord a{3, 5}, b{4, 5};
    const std::vector<float> a0 = draw(*s, a, 2);
    draw(*s, b, 2);
    draw(*s, b, 9);
    s->start_pixel_sample(a, 2);
    s->get_1d();  // a partial, abandoned sample
    EXPECT_EQ(draw(*s, a, 2), a0);
    // A fresh sampler and a clone agree too.
    EXPECT_EQ(draw(*make_sampler(GetParam(), 16, 7), a, 2), a0);
    auto c = s->clone();
    draw(*s, b, 0);
    EXPECT_EQ(draw(*c, a, 2), a0);
}

TEST_P(SamplerTypes, SeedsPixelsAndIndicesDecorrelate) {
    auto s = make_sampler(GetParam(), 16, 7);
    const std::vector<float> ref = draw(*s, {3, 5}, 2);
    auto other_seed = make_sampler(GetParam(), 16, 8);
    for (const std::vector<float>& v : {draw(*other_seed, {3, 5}, 2), draw(*s, {5, 3}, 2),
                                        draw(*s, {3, 6}, 2), draw(*s, {3, 5}, 3)}) {
        ASSERT_EQ(v.size(), ref.size());
        int same = 0;
        for (size_t i = 0; i < v.size(); ++i) same += v[i] == ref[i];
        EXPECT_EQ(same, 0);
    }
}

TEST_P(SamplerTypes, MomentsAreUniform) {
    // Values in [0, 1), mean 1/2 and no correlation between consecutive dimensions, within 5 sigma
    // of independent uniform numbers (stratification only lowers the variance).
    const uint32_t spp = 16;
    auto s = make_sampler(GetParam(), spp, 3);
    double sum = 0, cross = 0;
    size_t n = 0, pairs = 0;
    for (int px = 0; px < 64; ++px)
        for (uint32_t i = 0; i < spp; ++i) {
            const std::vector<float> v = draw(*s, {px, px / 8}, i);
            for (size_t k = 0; k < v.size(); ++k) {
                ASSERT_TRUE(v[k] >= 0 && v[k] < 1) << v[k];
                sum += v[k];
                ++n;
                if (k + 1 < v.size()) {
                    cross += (v[k] - 0.5) * (v[k + 1] - 0.5);
                    ++pairs;
                }
            }
        }
    EXPECT_NEAR(sum / n, 0.5, 5 * std::sqrt(1.0 / 12 / n));
    EXPECT_NEAR(cross / pairs, 0.0, 5 * (1.0 / 12) / std::sqrt(double(pairs)));
}

INSTANTIATE_TEST_SUITE_P(, SamplerTypes,
                         ::testing::Values(SamplerType::Independent, SamplerType::Stratified,
                                           SamplerType::Sobol, SamplerType::ZSobol,
                                           SamplerType::TabledSobol));

TEST(Sampler, InEffectAndMake) {
    // What a header records: tabled Sobol is the stratified sampler off powers of two.
    for (SamplerType type : {SamplerType::Independent, SamplerType::Stratified, SamplerType::Sobol,
                             SamplerType::ZSobol, SamplerType::TabledSobol})
        EXPECT_EQ(sampler_in_effect(type, 64), type);
    EXPECT_EQ(sampler_in_effect(SamplerType::TabledSobol, 48), SamplerType::Stratified);
    EXPECT_NE(dynamic_cast<StratifiedSampler*>(make_sampler(SamplerType::TabledSobol, 48, 0).get()),
              nullptr);
    EXPECT_EQ(make_sampler(SamplerType::Stratified, 12, 0)->samples_per_pixel(), 12u);
}

}  // namespace
}  // namespace penumbra
