// Warps from the unit square to common domains, each with its density. Directions are
// in the local frame (z up); densities are per unit solid angle or per unit area.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "core/math/vec.h"

namespace penumbra {

namespace warp_detail {

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

}  // namespace warp_detail

// Unit disk, Shirley-Chiu concentric map (preserves stratification); pdf = 1/pi per area.
Vec2 square_to_concentric_disk(Vec2 u);
// (cos a, sin a) for a in [-pi/4, pi/4], as the concentric map computes them (for tests).
Vec2 cos_sin_quarter_pi_for_test(float a);
// Regular n-gon inscribed in the unit circle (n >= 3), uniform by area: pick a triangle
// wedge, then a uniform point in it. pdf = 1/area of the polygon.
Vec2 square_to_polygon(Vec2 u, int blades, float rotation = 0);
float polygon_area(int blades);

Vec3 square_to_uniform_sphere(Vec2 u);
inline float uniform_sphere_pdf() { return kInv4Pi; }

Vec3 square_to_uniform_hemisphere(Vec2 u);
inline float uniform_hemisphere_pdf(Vec3 w) { return w.z >= 0 ? kInv2Pi : 0.0f; }

// Cosine-weighted hemisphere (Malley's method on the concentric disk). Inline: the
// path loop samples it at every diffuse bounce, and as a call its Vec2 argument and Vec3
// result are packed into and out of registers around a chain of a division, a
// polynomial and a square root.
inline Vec3 square_to_cosine_hemisphere(Vec2 u) {
    // z = sqrt(1 - r^2) from the disk radius runs beside the angle's division and
    // polynomial, where from the point's x and y it would wait for them.
    // (1 - r)(1 + r) keeps 1 - r^2 accurate near the rim.
    float r;
    const Vec2 d = warp_detail::concentric_disk(u, &r);
    const float z = std::sqrt(std::max(0.0f, (1 - r) * (1 + r)));
    return {d.x, d.y, z};
}
inline float cosine_hemisphere_pdf(Vec3 w) { return w.z > 0 ? w.z * kInvPi : 0.0f; }

// Uniform cone around +z with cos(theta_max) = cos_max; pdf = 1 / (2 pi (1 - cos_max)).
Vec3 square_to_uniform_cone(Vec2 u, float cos_max);
float uniform_cone_pdf(float cos_max);

// Uniform barycentrics (b1, b2) on a triangle (Heitz 2019 low-distortion map).
Vec2 square_to_triangle(Vec2 u);

}  // namespace penumbra
