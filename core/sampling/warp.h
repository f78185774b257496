// Warps from the unit square to common domains, each with its density. Directions are
// in the local frame (z up); densities are per unit solid angle or per unit area.
#pragma once

#include "core/math/vec.h"

namespace penumbra {

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

// Cosine-weighted hemisphere (Malley's method on the concentric disk).
Vec3 square_to_cosine_hemisphere(Vec2 u);
inline float cosine_hemisphere_pdf(Vec3 w) { return w.z > 0 ? w.z * kInvPi : 0.0f; }

// Uniform cone around +z with cos(theta_max) = cos_max; pdf = 1 / (2 pi (1 - cos_max)).
Vec3 square_to_uniform_cone(Vec2 u, float cos_max);
float uniform_cone_pdf(float cos_max);

// Uniform barycentrics (b1, b2) on a triangle (Heitz 2019 low-distortion map).
Vec2 square_to_triangle(Vec2 u);

}  // namespace penumbra
