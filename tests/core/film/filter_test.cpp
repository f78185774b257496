#include "core/film/filter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "support/chi2.h"

namespace penumbra {
namespace {

const char* const kFilters[] = {"box", "gaussian", "blackman-harris"};
const double kLevel = test::sidak_significance(0.01, 3);

// The integral of f over [-r, r] by a fine midpoint rule (the filters are smooth, or
// constant, inside their support).
double integral_1d(const Filter& f) {
    const int n = 200000;
    const double r = f.radius(), dx = 2 * r / n;
    double sum = 0;
    for (int i = 0; i < n; ++i) sum += f.eval_1d(float(-r + (i + 0.5) * dx));
    return sum * dx;
}

// Mean and standard error of a sample.
struct Moments {
    double sum = 0, sum2 = 0;
    size_t n = 0;
    void add(double v) {
        sum += v;
        sum2 += v * v;
        ++n;
    }
    double mean() const { return sum / n; }
    double std_error() const {
        return std::sqrt(std::max(0.0, sum2 / n - mean() * mean()) / (n - 1));
    }
};

class Filters : public ::testing::TestWithParam<const char*> {};

TEST_P(Filters, SamplesFollowTheFilter) {
    const auto f = make_filter(GetParam());
    const double r = f->radius(), norm = integral_1d(*f);
    test::PlanarChi2Options o;
    o.lo = {float(-r), float(-r)};
    o.hi = {float(r), float(r)};
    o.significance = kLevel;
    const test::Chi2Result res = test::chi2_planar(
        [&](Rng& rng) {
            return std::optional<Vec2>(f->sample({rng.next_float(), rng.next_float()}).offset);
        },
        [&](Vec2 p) { return std::abs(double(f->eval(p))) / (norm * norm); }, o);
    EXPECT_TRUE(res.passed) << GetParam() << "\n" << res.report;
    EXPECT_NEAR(res.pdf_integral, 1.0, 1e-4);
}

TEST_P(Filters, WeightsArePositiveAndNearlyConstant) {
    const auto f = make_filter(GetParam());
    const double integral = std::pow(integral_1d(*f), 2);
    Rng rng(11);
    Moments w;
    for (int i = 0; i < 100000; ++i) {
        const FilterSample s = f->sample({rng.next_float(), rng.next_float()});
        ASSERT_GT(s.weight, 0.0f) << s.offset.x << " " << s.offset.y;
        // pdf tabulates |f| at bin centers, so the weight is the integral times
        // f / f(bin center) per axis: at most 2 per axis, in a bin ending at a zero of f.
        ASSERT_LT(s.weight, 4.01 * integral);
        w.add(s.weight);
        if (std::string(GetParam()) == "box") {
            ASSERT_EQ(s.weight, 1.0f);
        }
    }
    const double cv = std::sqrt(w.sum2 / w.n - w.mean() * w.mean()) / w.mean();
    EXPECT_LT(cv, 0.05) << GetParam();
}

TEST_P(Filters, WeightsAreUnbiased) {
    // E[f / pdf] is the integral of f; and for a symmetric filter the weighted mean of a
    // linear ramp a + b x + c y is its value at the center, a, exactly in expectation.
    const auto f = make_filter(GetParam());
    const double integral = std::pow(integral_1d(*f), 2);
    const double b = 0.7, c = -1.3;
    Rng rng(12);
    Moments w, ramp;
    for (int i = 0; i < 200000; ++i) {
        const FilterSample s = f->sample({rng.next_float(), rng.next_float()});
        w.add(s.weight);
        ramp.add(s.weight * (b * s.offset.x + c * s.offset.y));
    }
    EXPECT_NEAR(w.mean(), integral, 5 * w.std_error() + 1e-6 * integral) << GetParam();
    EXPECT_NEAR(ramp.mean(), 0.0, 5 * ramp.std_error()) << GetParam();
}

TEST_P(Filters, IsSymmetricAndVanishesOutsideTheSupport) {
    const auto f = make_filter(GetParam());
    const float r = f->radius();
    for (float x : {0.0f, 0.1f, 0.37f, 0.49f, 0.8f, 1.2f, 1.49f}) {
        if (x > r) continue;
        // Up to float rounding: the window is a sum of cosines of (x + r) / 2r.
        EXPECT_NEAR(f->eval_1d(x), f->eval_1d(-x), 1e-6f) << x;
        EXPECT_GE(f->eval_1d(x), 0.0f) << x;
    }
    EXPECT_EQ(f->eval_1d(r * 1.01f), 0.0f);
    EXPECT_EQ(f->eval_1d(-r * 1.01f), 0.0f);
    EXPECT_EQ(f->eval({0, r * 1.5f}), 0.0f);
    EXPECT_EQ(f->name(), GetParam());
}

INSTANTIATE_TEST_SUITE_P(, Filters, ::testing::ValuesIn(kFilters));

// The box's closed form keeps the pixel sample's stratification exactly: the offset is
// u - 1/2, up to the rounding of one subtraction, and it stays inside the pixel.
TEST(Filter, BoxOffsetIsThePixelSampleMinusOneHalf) {
    const auto f = make_filter("box");
    for (float u : {0.0f, 0.25f, 0.5f, 0.7f, 0x1.fffffep-1f}) {
        const FilterSample s = f->sample({u, 1 - u * 0.5f});
        EXPECT_EQ(s.offset.x, u - 0.5f);
        EXPECT_EQ(s.offset.y, (1 - u * 0.5f) - 0.5f);
        EXPECT_LT(s.offset.x, 0.5f);
        EXPECT_EQ(s.weight, 1.0f);
    }
}

TEST(Filter, UnknownNameThrows) { EXPECT_THROW(make_filter("mitchell"), std::invalid_argument); }

}  // namespace
}  // namespace penumbra
