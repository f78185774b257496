#include "core/math/atan2.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace penumbra {
namespace {

// |got - exact| in units of the float spacing at the exact value.
double ulps(float got, double exact) {
    const float f = float(exact);
    const double spacing =
        double(std::nextafter(std::abs(f), std::numeric_limits<float>::infinity())) -
        std::abs(double(f));
    return std::abs(double(got) - exact) / spacing;
}

TEST(Atan2, WithinThreeUlp) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(-1, 1), exponent(-30, 30);
    double worst = 0;
    for (int i = 0; i < 2000000; ++i) {
        float y = unit(rng), x = unit(rng);
        // Also ratios far from 1 (every octant, near the axes).
        if (i % 3 == 1) y *= std::exp2(exponent(rng));
        if (i % 3 == 2) x *= std::exp2(exponent(rng));
        const double e = ulps(atan2_fast(y, x), std::atan2(double(y), double(x)));
        ASSERT_LE(e, 3.0) << "atan2(" << y << ", " << x << ")";
        worst = std::max(worst, e);
    }
    // The bound is near what the polynomial gives (2.7 ulp), so it can see a worse one.
    EXPECT_GT(worst, 1.5);
}

TEST(Atan2, AxesAndSignedZerosAsC) {
    const float zeros[2] = {0.0f, -0.0f};
    for (float y : zeros)
        for (float x : {0.0f, -0.0f, 1.0f, -1.0f, 1e-30f, -1e30f}) {
            const float got = atan2_fast(y, x), want = std::atan2(y, x);
            EXPECT_EQ(got, want) << "atan2(" << y << ", " << x << ")";
            EXPECT_EQ(std::signbit(got), std::signbit(want)) << "atan2(" << y << ", " << x << ")";
        }
    EXPECT_FLOAT_EQ(atan2_fast(1, 0), kPi / 2);
    EXPECT_FLOAT_EQ(atan2_fast(-1, 0), -kPi / 2);
    EXPECT_FLOAT_EQ(atan2_fast(1, 1), kPi / 4);
    EXPECT_FLOAT_EQ(atan2_fast(-1, -1), -3 * kPi / 4);
    EXPECT_FLOAT_EQ(atan2_fast(1e-3f, -1), kPi - 1e-3f);
}

}  // namespace
}  // namespace penumbra
