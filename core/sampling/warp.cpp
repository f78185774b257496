#include "core/sampling/warp.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace penumbra {

namespace {

// cos and sin of a in [-pi/4, pi/4] from Cephes' single-precision minimax polynomials
// (cosf.c, sinf.c without their range reduction, which this range does not need): worst
// 0.80 ulp for sin and 0.98 for cos against double over every float of the range
// (Warp.QuarterPiCosSinWithinAnUlp), where libm's sincosf is a call that the path loop
// paid for at every cosine-weighted bounce.
inline Vec2 cos_sin_quarter_pi(float a) {
    const float z = a * a;
    const float s = ((-1.9515295891e-4f * z + 8.3321608736e-3f) * z - 1.6666654611e-1f) * z * a + a;
    const float c =
        ((2.443315711809948e-5f * z - 1.388731625493765e-3f) * z + 4.166664568298827e-2f) * z * z -
        0.5f * z + 1.0f;
    return {c, s};
}

// c ? a : b by masks: GCC turns the ternary on floats into a branch, which on the
// concentric map's wedge (a coin flip per sample) mispredicts half the time.
inline float select(bool c, float a, float b) {
    uint32_t ua, ub;
    std::memcpy(&ua, &a, 4);
    std::memcpy(&ub, &b, 4);
    const uint32_t m = 0u - uint32_t(c);
    const uint32_t r = (ua & m) | (ub & ~m);
    float out;
    std::memcpy(&out, &r, 4);
    return out;
}

}  // namespace

Vec2 cos_sin_quarter_pi_for_test(float a) { return cos_sin_quarter_pi(a); }

namespace {

// Shirley-Chiu's map, with the point's radius (the major coordinate's magnitude) apart:
// known before the angle's division and polynomial, it lets the cosine warp's z run
// beside them.
inline Vec2 concentric_disk(Vec2 u, float* radius) {
    const float ox = 2 * u.x - 1, oy = 2 * u.y - 1;
    *radius = std::max(std::abs(ox), std::abs(oy));
    if (ox == 0 && oy == 0) return {0, 0};
    // Shirley-Chiu's two wedges: for |ox| > |oy| the angle is (pi/4) oy/ox, else
    // pi/2 - (pi/4) ox/oy, whose cos and sin are the sin and cos of (pi/4) ox/oy. So one
    // angle in [-pi/4, pi/4] serves both, and the wedge is chosen by selects, not by a
    // branch that mispredicts half the time.
    const bool x_major = std::abs(ox) > std::abs(oy);
    const float r = select(x_major, ox, oy);
    const float q = select(x_major, oy, ox);
    const Vec2 cs = cos_sin_quarter_pi((kPi / 4) * (q / r));
    const float along = r * cs.x, across = r * cs.y;
    return {select(x_major, along, across), select(x_major, across, along)};
}

}  // namespace

Vec2 square_to_concentric_disk(Vec2 u) {
    float radius;
    return concentric_disk(u, &radius);
}

float polygon_area(int blades) { return 0.5f * blades * std::sin(2 * kPi / blades); }

Vec2 square_to_polygon(Vec2 u, int blades, float rotation) {
    // All wedges have equal area, so choose one uniformly and reuse the leftover of u.x.
    const float scaled = u.x * blades;
    const int k = std::min(static_cast<int>(scaled), blades - 1);
    const float ux = scaled - k;
    const float a0 = rotation + 2 * kPi * k / blades;
    const float a1 = rotation + 2 * kPi * (k + 1) / blades;
    // Uniform point in the triangle (center, v0, v1).
    const Vec2 b = square_to_triangle({ux, u.y});
    const Vec2 v0{std::cos(a0), std::sin(a0)}, v1{std::cos(a1), std::sin(a1)};
    return v0 * b.x + v1 * b.y;
}

Vec3 square_to_uniform_sphere(Vec2 u) {
    const float z = 1 - 2 * u.x;
    const float r = std::sqrt(std::max(0.0f, 1 - z * z));
    const float phi = 2 * kPi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

Vec3 square_to_uniform_hemisphere(Vec2 u) {
    const float z = u.x;
    const float r = std::sqrt(std::max(0.0f, 1 - z * z));
    const float phi = 2 * kPi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

Vec3 square_to_cosine_hemisphere(Vec2 u) {
    // z = sqrt(1 - r^2) from the disk radius runs beside the angle's division and
    // polynomial; from the point's x and y it waited for them (4.7% of the point-light
    // Cornell box's profile, 3.3% this way). (1 - r)(1 + r) keeps 1 - r^2 accurate near
    // the rim.
    float r;
    const Vec2 d = concentric_disk(u, &r);
    const float z = std::sqrt(std::max(0.0f, (1 - r) * (1 + r)));
    return {d.x, d.y, z};
}

Vec3 square_to_uniform_cone(Vec2 u, float cos_max) {
    const float cos_theta = (1 - u.x) + u.x * cos_max;
    const float sin_theta = std::sqrt(std::max(0.0f, 1 - cos_theta * cos_theta));
    const float phi = 2 * kPi * u.y;
    return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

float uniform_cone_pdf(float cos_max) { return 1.0f / (2 * kPi * (1 - cos_max)); }

Vec2 square_to_triangle(Vec2 u) {
    // Heitz's two branches (halve the smaller coordinate, subtract it from the larger)
    // without a branch, which mispredicts half the time: the other coordinate minus half
    // of itself is its half exactly (Sterbenz), so the results are the branches' own.
    const float h = std::min(u.x, u.y) * 0.5f;
    return {u.x - h, u.y - h};
}

}  // namespace penumbra
