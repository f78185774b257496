// Uniform sampling of the solid angle a triangle subtends (Arvo 1995, "Stratified sampling
// of spherical triangles"), its inverse, and the bilinear warp that multiplies it by an
// approximate receiver cosine (pbrt-v4's "warp product sampling", section 6.5.4).
#pragma once

#include <optional>

#include "core/math/vec.h"

namespace penumbra {

// Solid angle (steradians) of the spherical triangle with unit vertex directions a, b, c
// (Van Oosterom & Strackee 1983: tan(omega / 2) = |a.(b x c)| / (1 + a.b + b.c + c.a)).
float spherical_triangle_area(Vec3 a, Vec3 b, Vec3 c);

// Solid angle that triangle v subtends at p; 0 when p is on a vertex.
float triangle_solid_angle(const Vec3 v[3], Vec3 p);

// A point of triangle v whose direction from p is uniform in the subtended solid angle:
// its barycentrics (b0, b1, b2) for (v[0], v[1], v[2]). The density is 1 / solid angle.
// Empty when the spherical triangle is degenerate (two directions parallel). Arvo's
// construction: u.x picks the area of the sub-triangle (a, b, c'), u.y a point on the arc
// from b to c'; u = (0, 0) and (1, 0) go to v[1], (0, 1) to v[0] and (1, 1) to v[2].
std::optional<Vec3> sample_spherical_triangle(const Vec3 v[3], Vec3 p, Vec2 u);

// The u that sample_spherical_triangle maps to direction w (unit, inside the triangle as
// seen from p), for the density of the bilinear warp in front of it (Arvo's SphTri.C).
Vec2 invert_spherical_triangle_sample(const Vec3 v[3], Vec3 p, Vec3 w);

// Bilinear density on [0,1]^2 through corner weights w = {f(0,0), f(1,0), f(0,1), f(1,1)}
// (non-negative), sampled by its marginal in y and conditional in x, each linear.
Vec2 sample_bilinear(Vec2 u, const float w[4]);
float bilinear_pdf(Vec2 p, const float w[4]);

// The corner weights of the warp product for a triangle seen from p with normal n: |cos|
// to each vertex direction, placed where sample_spherical_triangle maps the square's
// corners, floored at 0.01 so no part of the triangle loses all its density (pbrt-v4).
void receiver_cosine_weights(const Vec3 v[3], Vec3 p, Vec3 n, float w[4]);

}  // namespace penumbra
