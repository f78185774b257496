#include "core/film/filter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/statistics/chi2.h"

namespace penumbra {
namespace {

const char* const kFilters[] = {"box", "gaussian", "blackman-harris"};

FilterType filter_type(const std::string& name) {
    return name == "box" ? FilterType::Box
           : name == "gaussian" ? FilterType::Gaussian
                                : FilterType::BlackmanHarris;
}
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
    const auto f = make_filter(filter_type(GetParam()));
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

TEST_P(Filters, WeightsAreOne) {
    // The offsets' density is the filter itself, so no sample weighs more than another.
    const auto f = make_filter(filter_type(GetParam()));
    Rng rng(11);
    for (int i = 0; i < 10000; ++i)
        ASSERT_EQ(f->sample({rng.next_float(), rng.next_float()}).weight, 1.0f);
}

TEST_P(Filters, OffsetsAreCentred) {
    // For a symmetric filter the mean of a linear ramp a + b x + c y over the offsets is
    // its value at the center, a.
    const auto f = make_filter(filter_type(GetParam()));
    const double b = 0.7, c = -1.3;
    Rng rng(12);
    Moments ramp;
    for (int i = 0; i < 200000; ++i) {
        const FilterSample s = f->sample({rng.next_float(), rng.next_float()});
        ramp.add(b * s.offset.x + c * s.offset.y);
    }
    EXPECT_NEAR(ramp.mean(), 0.0, 5 * ramp.std_error()) << GetParam();
}

// The inverse-CDF table's density against the filter, with every u the sampler can
// give (its values are 24-bit fractions): the offsets' share of each of 300 bins
// against the filter's exact share, summed as an L1 distance. The table's equal-mass
// steps (Filter::kInverseSteps) make a staircase of the density, widest in the tails:
// 7.1e-5 for the Gaussian and 1.15e-4 for Blackman-Harris at 16,384 steps, 1.5e-4 and
// 2.6e-4 at 8,192, 7.9e-4 and 1.1e-3 at 2,048. The offsets also rise with u and stay in
// the support, so the pixel sample's stratification carries over to the film.
TEST_P(Filters, InverseTableIsTheFilterWithinItsSteps) {
    const auto f = make_filter(filter_type(GetParam()));
    const double r = f->radius();
    constexpr int kBinsOut = 300, kU = 1 << 24;
    std::vector<double> observed(kBinsOut, 0.0), expected(kBinsOut, 0.0);
    float previous = -std::numeric_limits<float>::infinity();
    for (int i = 0; i < kU; ++i) {
        const float x = f->sample_1d(i * 0x1p-24f);
        ASSERT_GE(x, previous) << i;
        ASSERT_GE(x, -r);
        ASSERT_LE(x, r);
        previous = x;
        const int bin = std::min(int((x + r) / (2 * r) * kBinsOut), kBinsOut - 1);
        observed[bin] += 1.0 / kU;
    }
    // Each bin's exact share by a fine midpoint rule (1000 points a bin).
    const int sub = 1000;
    const double dx = 2 * r / (kBinsOut * sub);
    double total = 0;
    for (int b = 0; b < kBinsOut; ++b) {
        for (int k = 0; k < sub; ++k)
            expected[b] += std::max(0.0f, f->eval_1d(float(-r + ((b * sub + k) + 0.5) * dx)));
        total += expected[b];
    }
    double l1 = 0;
    for (int b = 0; b < kBinsOut; ++b) l1 += std::abs(observed[b] - expected[b] / total);
    const bool box = std::string(GetParam()) == "box";  // u - 1/2: exact up to rounding
    EXPECT_LT(l1, box ? 1e-5 : 1.5e-4) << GetParam();
}

TEST_P(Filters, IsSymmetricAndVanishesOutsideTheSupport) {
    const auto f = make_filter(filter_type(GetParam()));
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
    const auto f = make_filter(FilterType::Box);
    for (float u : {0.0f, 0.25f, 0.5f, 0.7f, 0x1.fffffep-1f}) {
        const FilterSample s = f->sample({u, 1 - u * 0.5f});
        EXPECT_EQ(s.offset.x, u - 0.5f);
        EXPECT_EQ(s.offset.y, (1 - u * 0.5f) - 0.5f);
        EXPECT_LT(s.offset.x, 0.5f);
        EXPECT_EQ(s.weight, 1.0f);
    }
}

// Every pass of every render samples one shared filter per name: the same object each
// time, drawing what a filter of its own would.
TEST(Filter, SharedFiltersAreOnePerNameAndSampleAsTheirOwn) {
    for (const char* name : kFilters) {
        const Filter& shared = shared_filter(filter_type(name));
        EXPECT_EQ(&shared, &shared_filter(filter_type(name))) << name;
        EXPECT_EQ(shared.name(), name);
        const auto own = make_filter(filter_type(name));
        for (float u : {0.0f, 0.1f, 0.5f, 0.77f, 0x1.fffffep-1f}) {
            const FilterSample a = shared.sample({u, 1 - u}), b = own->sample({u, 1 - u});
            EXPECT_EQ(a.offset.x, b.offset.x) << name << " " << u;
            EXPECT_EQ(a.offset.y, b.offset.y) << name << " " << u;
            EXPECT_EQ(a.weight, b.weight);
        }
    }
}

}  // namespace
}  // namespace penumbra
