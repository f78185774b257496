#include "core/math/float4.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "support/float_bits.h"

namespace penumbra {
namespace {

using test::bits_of;

void expect_same_bits(Vec3 a, Vec3 b, const char* what) {
    EXPECT_EQ(bits_of(a.x), bits_of(b.x)) << what;
    EXPECT_EQ(bits_of(a.y), bits_of(b.y)) << what;
    EXPECT_EQ(bits_of(a.z), bits_of(b.z)) << what;
}

std::vector<float> test_values() {
    using L = std::numeric_limits<float>;
    std::vector<float> v = {0.0f,     -0.0f,     1.0f,      -1.0f,         L::denorm_min(),
                            L::min(), -L::max(), L::max(),  L::infinity(), -L::infinity(),
                            1e-30f,   3.0e38f,   -2.5e-39f, 0.1f,          -1e3f};
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> mantissa(-1, 1);
    std::uniform_int_distribution<int> exponent(-40, 40);
    for (int i = 0; i < 200; ++i) v.push_back(std::ldexp(mantissa(rng), exponent(rng)));
    return v;
}

// The hot path's Vec3 arithmetic in lanes (surface_point.cpp) must give the bits that
// Vec3's operators give: every lane operation is the scalar one.
TEST(Float4, Vec3LanesGiveTheBitsOfVec3Arithmetic) {
    const std::vector<float> v = test_values();
    const size_t n = v.size();
    for (size_t i = 0; i < n; ++i) {
        const Vec3 a(v[i], v[(i + 1) % n], v[(i + 2) % n]);
        const Vec3 b(v[(i * 7 + 3) % n], v[(i * 5 + 1) % n], v[(i * 3 + 2) % n]);
        const float s = v[(i * 11 + 5) % n];
        const F4 a4 = F4::load3(a), b4 = F4::load3(b);
        expect_same_bits(a4.xyz(), a, "load3 and xyz");
        expect_same_bits((a4 + b4).xyz(), a + b, "+");
        expect_same_bits((a4 - b4).xyz(), a - b, "-");
        expect_same_bits((a4 * b4).xyz(), a * b, "*");
        expect_same_bits((a4 * F4(s)).xyz(), a * s, "* scalar");
        expect_same_bits(abs4(a4).xyz(), Vec3(std::abs(a.x), std::abs(a.y), std::abs(a.z)), "abs");
        EXPECT_EQ(bits_of(a4.lane0()), bits_of(a.x));
    }
    // NaN keeps its payload through abs4 (only the sign bit is cleared).
    const float nan = -std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(bits_of(abs4(F4(nan)).lane0()), bits_of(nan) & 0x7fffffffu);
}

// load3 reads 12 bytes: a Vec3 at the very end of an array is read without going past it
// (AddressSanitizer would report the overrun).
TEST(Float4, Load3ReadsOnlyTheVec3) {
    const std::vector<Vec3> points = {{1, 2, 3}, {4, 5, 6}};
    expect_same_bits(F4::load3(points.back()).xyz(), points.back(), "last element");
}

TEST(Float4, SelectAndCompareAreLaneWise) {
    alignas(16) const float a[4] = {1, -2, 3, 0};
    alignas(16) const float b[4] = {0, -1, 3, -0.0f};
    alignas(16) float out[4];
    select(gt(F4::load(a), F4::load(b)), F4(10.0f), F4(20.0f)).store(out);
    EXPECT_EQ(out[0], 10);  // 1 > 0
    EXPECT_EQ(out[1], 20);  // -2 > -1 is false
    EXPECT_EQ(out[2], 20);  // equal
    EXPECT_EQ(out[3], 20);  // 0 > -0 is false
}

}  // namespace
}  // namespace penumbra
