// The adaptive decision on films with known halves: the minimum and step rules, the 3x3
// error window and the dilation.
#include "integrators/adaptive_sampling.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace penumbra {
namespace {

TEST(AdaptiveSampling, MinimumAndStepAreEven) {
    EXPECT_EQ(adaptive_min_spp(0.01), 64u);  // 16 / 0.01^0.3 = 63.7
    EXPECT_EQ(adaptive_min_spp(0.1), 32u);   // 31.9
    EXPECT_EQ(adaptive_min_spp(1.0), 16u);
    EXPECT_EQ(adaptive_min_spp(100.0), 8u);  // the floor
    for (double e : {0.003, 0.02, 0.05, 0.5}) EXPECT_EQ(adaptive_min_spp(e) % 2, 0u) << e;
    for (uint32_t done : {2u, 16u, 64u, 100u, 1000u, 4097u}) {
        EXPECT_EQ(adaptive_step(done) % 2, 0u) << done;
        EXPECT_GE(adaptive_step(done), 16u);
        EXPECT_GE(adaptive_step(done) + 2, done / 4) << done;
    }
}

// A film where every pixel's halves agree exactly (zero error) but one pixel's differ.
Film film_with_one_noisy_pixel(int w, int h, int nx, int ny) {
    AovSet aovs;
    aovs.add(Aov::Error);
    Film film(w, h, aovs);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int s = 0; s < 4; ++s) {
                AovRecord r;
                r.odd = (s & 1) != 0;
                const float v = (x == nx && y == ny) ? (r.odd ? 0.5f : 1.5f) : 1.0f;
                film.add_sample(x, y, Spectrum(v), 1, r);
            }
    return film;
}

TEST(AdaptiveSampling, ANoisyPixelKeepsItsWindowAndItsNeighboursActive) {
    const Film film = film_with_one_noisy_pixel(9, 7, 4, 3);
    // Halves 1.5 and 0.5 with two samples each: variance (1)^2 * 2 * 2 / 4^2 = 0.25 per
    // channel, mean 1: relative error sqrt(0.25 / 1.01).
    const double e2 = 0.25 / 1.01;
    EXPECT_NEAR(film.relative_error(4, 3), std::sqrt(e2), 1e-6);
    EXPECT_EQ(film.relative_error(0, 0), 0.0f);
    std::vector<uint8_t> active;
    // Every window holding the noisy pixel has 9 pixels: e2 / 9 against a target of 0.1
    // (0.01 squared) leaves them unconverged, and every pixel of theirs (within 2 of the
    // noisy one) active.
    EXPECT_EQ(update_active_pixels(film, 0.1, active), 25u);
    for (int y = 0; y < 7; ++y)
        for (int x = 0; x < 9; ++x)
            EXPECT_EQ(active[size_t(y) * 9 + x], std::abs(x - 4) <= 2 && std::abs(y - 3) <= 2)
                << x << "," << y;
    // A target above e2 / 9 stops every pixel, and one just below does not.
    const double window = std::sqrt(e2 / 9);
    EXPECT_EQ(update_active_pixels(film, window * 1.001, active), 0u);
    EXPECT_EQ(update_active_pixels(film, window * 0.999, active), 25u);
}

TEST(AdaptiveSampling, AnEdgePixelsWindowIsSmaller) {
    const Film film = film_with_one_noisy_pixel(5, 5, 0, 0);
    std::vector<uint8_t> active;
    // The corner's window has 4 pixels: e2 / 4, the most any window holds.
    const double corner = std::sqrt(0.25 / 1.01 / 4);
    EXPECT_EQ(update_active_pixels(film, corner * 1.001, active), 0u);
    // Just below: only the corner's window is unconverged, and its 4 pixels stay.
    EXPECT_EQ(update_active_pixels(film, corner * 0.999, active), 4u);
    EXPECT_TRUE(active[0] && active[1] && active[5] && active[6]);
}

}  // namespace
}  // namespace penumbra
