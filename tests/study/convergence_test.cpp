// Error metrics and the convergence fits used by `penumbra converge`, on inputs whose
// answers are known exactly.
#include "core/film/image_error.h"
#include "study/convergence.h"

#include <gtest/gtest.h>

#include <cmath>

namespace penumbra {
namespace {

Image constant(int w, int h, float r, float g, float b) {
    Image img(w, h, 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            img.at(x, y)[0] = r;
            img.at(x, y)[1] = g;
            img.at(x, y)[2] = b;
        }
    return img;
}

TEST(Convergence, MseAndRelMseAverageOverPixelsAndRgb) {
    const Image ref = constant(4, 2, 1.0f, 0.0f, 2.0f);
    Image img = ref;
    img.at(3, 1)[0] = 3.0f;  // one channel of one pixel off by 2
    const double n = 4 * 2 * 3;
    EXPECT_DOUBLE_EQ(mean_squared_error(img, ref), 4.0 / n);
    EXPECT_DOUBLE_EQ(relative_mse(img, ref), 4.0 / (1.0 + kRelMseEpsilon) / n);
    // On a black reference pixel the epsilon alone divides.
    img = ref;
    img.at(0, 0)[1] = 0.5f;
    EXPECT_DOUBLE_EQ(relative_mse(img, ref, 0.25), 0.25 / 0.25 / n);
    // Alpha is not compared; an RGBA image matches an RGB reference.
    Image rgba(4, 2, 4);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x) {
            float* p = rgba.at(x, y);
            p[0] = 1, p[1] = 0, p[2] = 2, p[3] = 0.5f;
        }
    EXPECT_EQ(mean_squared_error(rgba, ref), 0.0);
}

TEST(Convergence, SlopeOfAnExactPowerLaw) {
    std::vector<double> spp, mse;
    for (double n = 1; n <= 1024; n *= 2) {
        spp.push_back(n);
        mse.push_back(0.3 * std::pow(n, -1.0));
    }
    EXPECT_NEAR(*log_log_slope(spp, mse), -1.0, 1e-12);
    for (double& e : mse) e = e * e;  // n^-2
    EXPECT_NEAR(*log_log_slope(spp, mse), -2.0, 1e-12);
    // Undetermined: one x value, or fewer than two usable points.
    EXPECT_FALSE(log_log_slope({4, 4, 4}, {1, 2, 3}));
    EXPECT_FALSE(log_log_slope({1, 2}, {1, 0}));
}

TEST(Convergence, TimeToErrorInterpolatesAndExtrapolatesInLogLog) {
    // error = 0.1 / t: reaching 0.01 takes 10 s.
    const std::vector<double> t = {1, 4, 16, 64}, e = {0.1, 0.025, 0.00625, 0.0015625};
    std::optional<TimeToError> r = time_to_error(t, e, 0.01);
    ASSERT_TRUE(r);
    EXPECT_NEAR(r->seconds, 10.0, 1e-9);
    EXPECT_FALSE(r->extrapolated);
    EXPECT_FALSE(r->at_most);
    // Beyond the last point: along the fitted power law.
    r = time_to_error(t, e, 1e-4);
    ASSERT_TRUE(r);
    EXPECT_NEAR(r->seconds, 1000.0, 1e-6);
    EXPECT_TRUE(r->extrapolated);
    // Already there at the first point.
    r = time_to_error(t, e, 0.5);
    EXPECT_EQ(r->seconds, 1.0);
    EXPECT_TRUE(r->at_most);
    EXPECT_FALSE(r->extrapolated);
    // The first crossing counts even if a later noisy point rises again. In log-log,
    // 0.1 is halfway from 0.2 to 0.05, so the time is halfway from 1 to 2: sqrt(2).
    r = time_to_error({1, 2, 4}, {0.2, 0.05, 0.3}, 0.1);
    EXPECT_NEAR(r->seconds, std::sqrt(2.0), 1e-12);
}

TEST(Convergence, TimeToErrorThatNeverFallsIsUnknown) {
    EXPECT_FALSE(time_to_error({1, 2, 4}, {0.5, 0.5, 0.6}, 0.1));
    EXPECT_FALSE(time_to_error({}, {}, 0.1));
}

}  // namespace
}  // namespace penumbra
