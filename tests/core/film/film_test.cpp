#include "core/film/film.h"

#include <gtest/gtest.h>

#include <limits>

namespace penumbra {
namespace {

Vec4 pixel(const Image& img, int x, int y) {
    const float* p = img.at(x, y);
    return {p[0], p[1], p[2], p[3]};
}

TEST(Film, AveragesSamplesByWeight) {
    Film film(3, 2);
    film.add_sample(1, 0, {1, 2, 3}, 1.0f);
    film.add_sample(1, 0, {3, 2, 1}, 3.0f);
    film.add_sample(2, 1, {0.5f, 0.25f, 4}, 0.2f);  // a lone sample: its own value
    const Image img = film.resolve();
    ASSERT_EQ(img.width, 3);
    ASSERT_EQ(img.height, 2);
    ASSERT_EQ(img.channels, 4);
    const Vec4 a = pixel(img, 1, 0);
    EXPECT_FLOAT_EQ(a.x, (1 * 1 + 3 * 3) / 4.0f);
    EXPECT_FLOAT_EQ(a.y, 2.0f);
    EXPECT_FLOAT_EQ(a.z, (3 * 1 + 1 * 3) / 4.0f);
    EXPECT_FLOAT_EQ(a.w, 1.0f);
    const Vec4 b = pixel(img, 2, 1);
    EXPECT_FLOAT_EQ(b.x, 0.5f);
    EXPECT_FLOAT_EQ(b.y, 0.25f);
    EXPECT_FLOAT_EQ(b.z, 4.0f);
    // A pixel without samples is black, opaque.
    const Vec4 empty = pixel(img, 0, 0);
    EXPECT_EQ(empty.x, 0.0f);
    EXPECT_EQ(empty.w, 1.0f);
    EXPECT_EQ(film.nonfinite_samples(), 0u);
}

TEST(Film, NonFiniteSamplesAreCountedAndDropped) {
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    Film film(2, 2);
    film.add_sample(0, 1, {0.25f, 0.5f, 1}, 2.0f);
    film.add_sample(0, 1, {nan, 0, 0}, 1.0f);
    film.add_sample(0, 1, {0, inf, 0}, 1.0f);
    film.add_sample(0, 1, {0, 0, -inf}, 1.0f);
    film.add_sample(1, 0, {nan, nan, nan}, 1.0f);
    EXPECT_EQ(film.nonfinite_samples(), 4u);
    const Image img = film.resolve();
    const Vec4 p = pixel(img, 0, 1);
    EXPECT_FLOAT_EQ(p.x, 0.25f);
    EXPECT_FLOAT_EQ(p.y, 0.5f);
    EXPECT_FLOAT_EQ(p.z, 1.0f);
    const Vec4 q = pixel(img, 1, 0);  // only a NaN arrived: still black, not NaN
    EXPECT_EQ(q.x, 0.0f);
    EXPECT_EQ(q.y, 0.0f);
}

}  // namespace
}  // namespace penumbra
