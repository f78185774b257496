#include "core/math/vec.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace penumbra {
namespace {

// The values where a bit trick could part from the comparisons it replaces: both zeros,
// the smallest denormals (a single low bit), the sign bit alone, NaNs, infinities, the
// extremes.
std::vector<float> edge_values() {
    using L = std::numeric_limits<float>;
    return {0.0f,          -0.0f,         L::denorm_min(), -L::denorm_min(), L::min(),
            -L::min(),     1.0f,          -1.0f,           L::max(),         -L::max(),
            L::infinity(), -L::infinity(), L::quiet_NaN(), -L::quiet_NaN(),  1e-30f};
}

// is_black and is_finite against their branching componentwise forms: every triple of edge
// values, in every position, gives the same answer.
TEST(Vec3Tests, IsBlackAndIsFiniteAgreeWithComponentwiseComparisons) {
    const std::vector<float> v = edge_values();
    int checked = 0;
    for (float x : v)
        for (float y : v)
            for (float z : v) {
                const Vec3 a(x, y, z);
                EXPECT_EQ(is_black(a), x == 0 && y == 0 && z == 0) << x << " " << y << " " << z;
                EXPECT_EQ(is_finite(a), std::isfinite(x) && std::isfinite(y) && std::isfinite(z))
                    << x << " " << y << " " << z;
                ++checked;
            }
    EXPECT_EQ(checked, int(v.size() * v.size() * v.size()));
    EXPECT_TRUE(is_black(Vec3(-0.0f, 0.0f, -0.0f)));
    EXPECT_FALSE(is_black(Vec3(0, 0, std::numeric_limits<float>::denorm_min())));
    EXPECT_FALSE(is_finite(Vec3(0, std::numeric_limits<float>::infinity(), 0)));
    EXPECT_TRUE(is_finite(Vec3(std::numeric_limits<float>::max(), 0, 0)));
}

}  // namespace
}  // namespace penumbra
