#include "core/accel/ray_box.h"

#include <gtest/gtest.h>

#include <limits>

namespace penumbra {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kLo[3] = {-1, -1, -1};
const float kHi[3] = {1, 1, 1};

bool hits(Vec3 o, Vec3 d, float tmin = 0, float tmax = kInf, float* t_enter = nullptr) {
    Ray r;
    r.o = o;
    r.d = d;
    r.tmin = tmin;
    r.tmax = tmax;
    const RayBoxPrecomp p(r);
    float t;
    const bool hit = ray_box(kLo, kHi, p, tmax, &t);
    if (t_enter) *t_enter = t;
    return hit;
}

TEST(RayBox, EntryIsTheLastEntryPlane) {
    float t;
    ASSERT_TRUE(hits({-3, 0.5f, 0}, {1, 0, 0}, 0, kInf, &t));
    EXPECT_FLOAT_EQ(t, 2.0f);
    // Diagonal: enters through x = -1 at t = 2 and y = -1 at t = 1.5; the later wins.
    ASSERT_TRUE(hits({-3, -2.5f, 0}, {1, 1, 0}, 0, kInf, &t));
    EXPECT_FLOAT_EQ(t, 2.0f);
    // In the y slab over [-0.5, 1.5], in the x slab over [2, 4]: a miss.
    EXPECT_FALSE(hits({-3, -0.5f, 0}, {1, 1, 0}));
}

TEST(RayBox, ZeroDirectionComponentsUseInfinities) {
    // d = (1, 0, 0) and (1, -0, -0): inv_d is +-inf on y and z.
    EXPECT_TRUE(hits({-3, 0.5f, 0.5f}, {1, 0, 0}));
    EXPECT_TRUE(hits({-3, 0.5f, 0.5f}, {1, -0.0f, -0.0f}));
    EXPECT_FALSE(hits({-3, 1.5f, 0}, {1, 0, 0}));  // outside the y slab, never enters
    EXPECT_FALSE(hits({-3, -1.5f, 0}, {1, -0.0f, 0}));
    EXPECT_FALSE(hits({3, 0, 0}, {1, 0, 0}));  // behind the origin
    EXPECT_TRUE(hits({0, 0, 0}, {0, 0, -1}));  // from inside
}

TEST(RayBox, RaysAlongFacesAndEdgesHit) {
    // Origins exactly on the y = 1 or y = -1 plane with d.y = +-0: 0 * inf = NaN for that
    // slab, which must not reject the ray (the box is closed).
    for (float sy : {1.0f, -1.0f})
        for (float dy : {0.0f, -0.0f}) {
            EXPECT_TRUE(hits({-3, sy, 0}, {1, dy, 0})) << sy << " " << dy;
            EXPECT_TRUE(hits({0, sy, -3}, {0, dy, 1})) << sy << " " << dy;
        }
    // Along an edge (two zero components, both origins on planes) and a corner line.
    EXPECT_TRUE(hits({-3, 1, 1}, {1, 0, 0}));
    EXPECT_TRUE(hits({1, 1, -5}, {0, 0, 1}));
    // Just off the face misses.
    EXPECT_FALSE(hits({-3, std::nextafter(1.0f, 2.0f), 0}, {1, 0, 0}));
}

TEST(RayBox, IntervalIsRespected) {
    EXPECT_FALSE(hits({-3, 0, 0}, {1, 0, 0}, 0, 1.5f));  // ends before the box
    EXPECT_TRUE(hits({-3, 0, 0}, {1, 0, 0}, 0, 2.0f));   // ends on the face
    EXPECT_FALSE(hits({-3, 0, 0}, {1, 0, 0}, 4.5f));     // starts after it
    EXPECT_TRUE(hits({-3, 0, 0}, {1, 0, 0}, 4.0f));      // starts on the far face
}

TEST(RayBox, NanAndInfiniteRaysMiss) {
    EXPECT_FALSE(hits({kNaN, 0, 0}, {1, 0, 0}));
    EXPECT_FALSE(hits({0, 0, 0}, {kNaN, 0, 0}));
    EXPECT_FALSE(hits({0, 0, 0}, {kNaN, kNaN, kNaN}));
    EXPECT_FALSE(hits({kInf, 0, 0}, {-1, 0, 0}));
    EXPECT_FALSE(hits({-kInf, 0, 0}, {1, 0, 0}));
    EXPECT_FALSE(hits({0, 0, 0}, {kInf, 0, 0}));
    EXPECT_FALSE(hits({0, 0, 0}, {0, 0, 0}));        // no direction
    EXPECT_FALSE(hits({0, 0, 0}, {1, 0, 0}, kNaN));  // NaN interval ends
    EXPECT_FALSE(hits({0, 0, 0}, {1, 0, 0}, 0, kNaN));
    EXPECT_FALSE(hits({0, 0, 0}, {1, 0, 0}, 2, 1));  // empty interval
    Ray r;
    r.o = {kNaN, 0, 0};
    r.d = {1, 0, 0};
    const RayBoxPrecomp p(r);
    EXPECT_FALSE(p.valid);
    float t;
    EXPECT_FALSE(ray_box(kLo, kHi, p, kInf, &t));  // whatever tmax the caller passes
}

}  // namespace
}  // namespace penumbra
