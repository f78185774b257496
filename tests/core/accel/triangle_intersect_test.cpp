#include "core/accel/triangle_intersect.h"

#include <gtest/gtest.h>

#include <limits>

#include "core/sampling/rng.h"

namespace penumbra {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

std::optional<TriangleHit> hit(Vec3 o, Vec3 d, Vec3 p0, Vec3 p1, Vec3 p2, float tmin = 0,
                               float tmax = kInf) {
    Ray r;
    r.o = o;
    r.d = d;
    TriangleHit h;
    if (!intersect_triangle(TrianglePrecomp(r), p0, p1, p2, tmin, tmax, &h)) return std::nullopt;
    return h;
}

const Vec3 kP0(0, 0, 0), kP1(1, 0, 0), kP2(0, 1, 0);

TEST(TriangleIntersect, BarycentricsFollowEmbree) {
    // b1 weighs vertex 1, b2 vertex 2: p = (1 - b1 - b2) p0 + b1 p1 + b2 p2.
    const auto h = hit({0.2f, 0.3f, 2}, {0, 0, -1}, kP0, kP1, kP2);
    ASSERT_TRUE(h);
    EXPECT_FLOAT_EQ(h->t, 2.0f);
    EXPECT_NEAR(h->b1, 0.2f, 1e-6f);
    EXPECT_NEAR(h->b2, 0.3f, 1e-6f);
    // Both faces, any dominant axis and sign of the direction.
    Rng rng(7);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 target(rng.next_float() * 0.5f, rng.next_float() * 0.5f, 0);
        const Vec3 o(4 * rng.next_float() - 2, 4 * rng.next_float() - 2,
                     rng.next_float() < 0.5f ? -1.5f : 1.5f);
        const auto hh = hit(o, (target - o) * 0.5f, kP0, kP1, kP2);
        ASSERT_TRUE(hh) << i;
        EXPECT_NEAR(hh->t, 2.0f, 1e-5f);
        EXPECT_NEAR(hh->b1, target.x, 1e-5f);
        EXPECT_NEAR(hh->b2, target.y, 1e-5f);
    }
}

TEST(TriangleIntersect, IntervalIsClosed) {
    // The hit is at exactly t = 2 (all values exact in float).
    EXPECT_TRUE(hit({0.25f, 0.25f, 2}, {0, 0, -1}, kP0, kP1, kP2, 0, 2));
    EXPECT_TRUE(hit({0.25f, 0.25f, 2}, {0, 0, -1}, kP0, kP1, kP2, 2, 3));
    EXPECT_FALSE(hit({0.25f, 0.25f, 2}, {0, 0, -1}, kP0, kP1, kP2, 2.001f, 3));
    EXPECT_FALSE(hit({0.25f, 0.25f, 2}, {0, 0, -1}, kP0, kP1, kP2, 0, 1.999f));
    EXPECT_FALSE(hit({0.25f, 0.25f, -2}, {0, 0, -1}, kP0, kP1, kP2));  // behind
}

TEST(TriangleIntersect, SharedEdgesAndVerticesAreNeverMissed) {
    // A closed, non-planar fan of six triangles around vertex c, and rays through points
    // of its inner edges (c included): each point is inside the fan, so at least one
    // triangle must report every ray, however the rounding of the edge functions falls.
    const Vec3 c(0.1f, 0.2f, 0.3f);
    Vec3 ring[6];
    for (int k = 0; k < 6; ++k)
        ring[k] = c + Vec3(std::cos(k * kPi / 3), 0.7f * std::sin(k * kPi / 3),
                           0.2f * std::sin(2.0f * k));
    Rng rng(3);
    int missed = 0, rays = 0;
    for (int trial = 0; trial < 50; ++trial)
        for (int k = 0; k < 6; ++k)
            for (int s = 0; s < 16; ++s) {
                const Vec3 target = lerp(c, ring[k], s / 16.0f);
                const Vec3 o = target + Vec3(rng.next_float() - 0.5f, rng.next_float() - 0.5f,
                                             rng.next_float() < 0.5f ? -3.0f : 3.0f);
                bool any = false;
                for (int f = 0; f < 6; ++f)
                    any = any || hit(o, target - o, c, ring[f], ring[(f + 1) % 6]).has_value();
                missed += !any;
                ++rays;
            }
    EXPECT_EQ(missed, 0) << "of " << rays;
}

TEST(TriangleIntersect, DegenerateTrianglesAndNanRaysMiss) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_FALSE(hit({0.5f, 0, 1}, {0, 0, -1}, kP0, kP1, kP1));            // two equal vertices
    EXPECT_FALSE(hit({0.5f, 0, 1}, {0, 0, -1}, kP0, kP1, Vec3(2, 0, 0)));  // collinear
    EXPECT_FALSE(hit({0.25f, 0.25f, 1}, {0, 0, 0}, kP0, kP1, kP2));        // no direction
    EXPECT_FALSE(hit({nan, 0.25f, 1}, {0, 0, -1}, kP0, kP1, kP2));
    EXPECT_FALSE(hit({0.25f, 0.25f, 1}, {nan, 0, -1}, kP0, kP1, kP2));
    EXPECT_FALSE(hit({0.25f, 0.25f, 1}, {0, 0, -1}, kP0, kP1, Vec3(0, nan, 0)));
    // Infinite rays never get here: Accel answers them (is_traceable, Degenerate tests).
    // In the plane of the triangle: parallel, no hit.
    EXPECT_FALSE(hit({-1, 0.25f, 0}, {1, 0, 0}, kP0, kP1, kP2));
}

}  // namespace
}  // namespace penumbra
