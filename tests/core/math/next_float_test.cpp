#include "core/math/next_float.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "support/float_bits.h"

namespace penumbra {
namespace {

using test::bits_of;

// Bitwise equality, so that -0 and +0 differ.
void expect_same_as_nextafter(float v) {
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_EQ(bits_of(next_float_up(v)), bits_of(std::nextafter(v, inf))) << v;
    EXPECT_EQ(bits_of(next_float_down(v)), bits_of(std::nextafter(v, -inf))) << v;
}

TEST(NextFloat, MatchesNextafterAtTheEdges) {
    using L = std::numeric_limits<float>;
    for (float v : {0.0f, -0.0f, L::denorm_min(), -L::denorm_min(), 2 * L::denorm_min(),
                    L::min(), -L::min(), std::nextafter(L::min(), 0.0f),
                    -std::nextafter(L::min(), 0.0f), 1.0f, -1.0f, L::epsilon(), 0.5f, 2.0f,
                    -2.0f, L::max(), -L::max(), L::infinity(), -L::infinity()})
        expect_same_as_nextafter(v);
    EXPECT_TRUE(std::isnan(next_float_up(L::quiet_NaN())));
    EXPECT_TRUE(std::isnan(next_float_down(L::quiet_NaN())));
}

TEST(NextFloat, MatchesNextafterOnRandomBitPatterns) {
    std::mt19937 rng(7);
    for (int i = 0; i < 100000; ++i) {
        const uint32_t b = rng();
        float v;
        std::memcpy(&v, &b, sizeof v);
        if (std::isnan(v)) continue;
        expect_same_as_nextafter(v);
    }
}

}  // namespace
}  // namespace penumbra
