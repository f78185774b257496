#include "core/accel/triangle_plane.h"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>

#include "core/sampling/rng.h"

namespace penumbra {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// triangle_plane_hit's formulas on Vec3, one float operation at a time: the F4 code must
// give these bits.
bool scalar_plane_hit(const TrianglePlane& tp, Vec3 o, Vec3 d, TriangleHit* hit) {
    const float nd = dot(tp.n, d);
    if (nd == 0 || std::isnan(nd)) return false;
    const float t = dot(tp.n, tp.p0 - o) / nd;
    const Vec3 q = (o + d * t) - tp.p0;
    hit->t = t;
    hit->b1 = dot(q, tp.g1);
    hit->b2 = dot(q, tp.g2);
    return std::isfinite(t) && std::isfinite(hit->b1) && std::isfinite(hit->b2);
}

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Checks one case against the scalar formulas; the plane is copied into an array with
// another plane after it, as EmbreeAccel stores them.
void expect_as_scalar(const TrianglePlane& tp, Vec3 o, Vec3 d, int i) {
    TrianglePlane planes[2] = {tp, {}};
    Ray ray;
    ray.o = o;
    ray.d = d;
    TriangleHit want{}, got{};
    const bool want_hit = scalar_plane_hit(tp, o, d, &want);
    ASSERT_EQ(triangle_plane_hit(planes[0], ray, &got), want_hit) << i;
    if (!want_hit) return;
    EXPECT_TRUE(same_bits(got.t, want.t)) << i << ": " << got.t << " " << want.t;
    EXPECT_TRUE(same_bits(got.b1, want.b1)) << i << ": " << got.b1 << " " << want.b1;
    EXPECT_TRUE(same_bits(got.b2, want.b2)) << i << ": " << got.b2 << " " << want.b2;
}

TEST(TrianglePlane, BarycentricsAndDistanceOfAKnownHit) {
    const TrianglePlane tp = make_triangle_plane({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    Ray ray;
    ray.o = {0.2f, 0.3f, 2};
    ray.d = {0, 0, -1};
    TriangleHit h;
    ASSERT_TRUE(triangle_plane_hit(tp, ray, &h));
    EXPECT_EQ(h.t, 2.0f);
    EXPECT_NEAR(h.b1, 0.2f, 1e-7f);
    EXPECT_NEAR(h.b2, 0.3f, 1e-7f);
}

TEST(TrianglePlane, BitsOfTheScalarFormulas) {
    // Random triangles at scales from 1e-3 to 1e3, rays from anywhere, aimed near them
    // and grazing them, so that every lane's rounding matters.
    Rng rng(11);
    auto coord = [&](float scale) { return (2 * rng.next_float() - 1) * scale; };
    for (int i = 0; i < 200000; ++i) {
        const float scale = std::pow(10.0f, 6 * rng.next_float() - 3);
        const Vec3 c(coord(100), coord(100), coord(100));
        const Vec3 p0 = c + Vec3(coord(scale), coord(scale), coord(scale));
        const Vec3 p1 = c + Vec3(coord(scale), coord(scale), coord(scale));
        const Vec3 p2 = c + Vec3(coord(scale), coord(scale), coord(scale));
        const TrianglePlane tp = make_triangle_plane(p0, p1, p2);
        const Vec3 o(coord(300), coord(300), coord(300));
        Vec3 d = (p0 + (p1 - p0) * rng.next_float() + (p2 - p0) * rng.next_float()) - o;
        if (i % 4 == 0) d = d - tp.n * (dot(d, tp.n) / dot(tp.n, tp.n)) * 0.999999f;
        expect_as_scalar(tp, o, d, i);
    }
}

TEST(TrianglePlane, NoHitWhereTheScalarFormulasHaveNone) {
    const TrianglePlane tp = make_triangle_plane({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    // Parallel to the plane, in it, NaN, an overflowing t, and a degenerate triangle.
    expect_as_scalar(tp, {0.2f, 0.2f, 1}, {1, 0, 0}, 0);
    expect_as_scalar(tp, {0.2f, 0.2f, 0}, {1, 1, 0}, 1);
    expect_as_scalar(tp, {kNaN, 0, 1}, {0, 0, -1}, 2);
    expect_as_scalar(tp, {0, 0, 1}, {kNaN, 0, -1}, 3);
    expect_as_scalar(tp, {0, 0, 3e38f}, {1, 0, -1e-30f}, 4);
    expect_as_scalar(tp, {0, 0, kInf}, {0, 0, -1}, 5);
    const TrianglePlane flat = make_triangle_plane({0, 0, 0}, {1, 1, 1}, {2, 2, 2});
    expect_as_scalar(flat, {0, 0, 1}, {0, 0, -1}, 6);
    TriangleHit h;
    Ray ray;
    ray.o = {0.2f, 0.2f, 1};
    ray.d = {1, 0, 0};
    EXPECT_FALSE(triangle_plane_hit(tp, ray, &h));
    ray.o = {0, 0, 1};
    ray.d = {0, 0, -1};
    EXPECT_FALSE(triangle_plane_hit(flat, ray, &h));
}

}  // namespace
}  // namespace penumbra
