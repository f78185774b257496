#include "core/math/portable_math.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>

namespace penumbra {
namespace {

// Distance in units in the last place between two finite floats of the same sign, or
// between a float and zero.
int64_t ulps(float a, float b) {
    int32_t ia, ib;
    std::memcpy(&ia, &a, 4);
    std::memcpy(&ib, &b, 4);
    if (ia < 0) ia = INT32_MIN - ia;
    if (ib < 0) ib = INT32_MIN - ib;
    return std::abs(int64_t(ia) - int64_t(ib));
}

// The float versions are the double result rounded once; the double result is within
// a few 1e-16 of the true value (fdlibm's kernels on |r| <= pi/4, three-part pi/2), so
// a float result is the correctly rounded one or, where the true value lies within
// 1e-16 relative of a midpoint between floats, its neighbour: at most 1 ulp from x87's
// long double sinl/cosl rounded to float (64-bit significands: the reference is off by
// far less than that margin).
TEST(PortableMath, FloatSinCosAreWithinOneUlpOfLongDouble) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> wide(-1000.0f, 1000.0f), narrow(-4.0f, 4.0f);
    int64_t worst = 0;
    int off_by_one = 0;
    for (int i = 0; i < 400000; ++i) {
        const float x = i % 2 ? wide(rng) : narrow(rng);
        float s, c;
        portable_sincos(x, &s, &c);
        const float rs = static_cast<float>(std::sin(static_cast<long double>(x)));
        const float rc = static_cast<float>(std::cos(static_cast<long double>(x)));
        const int64_t es = ulps(s, rs), ec = ulps(c, rc);
        worst = std::max({worst, es, ec});
        off_by_one += (es == 1) + (ec == 1);
        ASSERT_LE(std::max(es, ec), 1) << "x = " << x;
        EXPECT_EQ(portable_sin(x), s);
        EXPECT_EQ(portable_cos(x), c);
    }
    // Nearly always the correctly rounded float: a midpoint within 1e-16 is rare.
    EXPECT_LT(off_by_one, 400) << "of 800000";
}

TEST(PortableMath, DoubleSinCosAndExpAreAccurate) {
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> angle(-1e5, 1e5), power(-700, 700);
    double worst_trig = 0, worst_exp = 0;
    for (int i = 0; i < 200000; ++i) {
        const double x = angle(rng);
        const long double xl = x;
        worst_trig = std::max({worst_trig, double(std::fabs(portable_sin(x) - std::sin(xl))),
                               double(std::fabs(portable_cos(x) - std::cos(xl)))});
        const double y = power(rng);
        const long double ey = std::exp(static_cast<long double>(y));
        worst_exp = std::max(worst_exp, double(std::fabs((portable_exp(y) - ey) / ey)));
    }
    // Reduction of |x| <= 1e5: n pi/2 with n < 2^17 and 99 bits of pi/2, exact products
    // for the first two parts; the kernels' error ~1 ulp. 4 ulps of 1 in all.
    EXPECT_LT(worst_trig, 4 * 0x1p-53);
    // The reduction k ln 2 exact in its high part, 13 Taylor terms and Horner's rounding:
    // a few ulps.
    EXPECT_LT(worst_exp, 4 * 0x1p-53);
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.3g %.3g", worst_trig, worst_exp);
    RecordProperty("worst_trig_exp", buf);
}

TEST(PortableMath, SpecialValues) {
    EXPECT_EQ(portable_sin(0.0f), 0.0f);
    EXPECT_EQ(portable_cos(0.0f), 1.0f);
    EXPECT_TRUE(std::signbit(portable_sin(-0.0f)));
    EXPECT_TRUE(std::isnan(portable_sin(std::numeric_limits<float>::infinity())));
    EXPECT_TRUE(std::isnan(portable_cos(std::numeric_limits<float>::quiet_NaN())));
    EXPECT_EQ(portable_exp(0.0), 1.0);
    EXPECT_EQ(portable_exp(-1000.0), 0.0);
    EXPECT_TRUE(std::isinf(portable_exp(1000.0)));
    EXPECT_TRUE(std::isnan(portable_exp(std::nan(""))));
    // A float's sin at a huge argument is still a number in [-1, 1].
    const float big = portable_sin(1e30f);
    EXPECT_TRUE(big >= -1 && big <= 1) << big;
}

}  // namespace
}  // namespace penumbra
