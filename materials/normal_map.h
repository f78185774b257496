// Normal-mapped shading normals that the viewer can see: a mapped normal is bent, where
// needed, so that the view direction lies above it and its mirror direction above the
// surface.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/math/vec.h"

namespace penumbra {

// The shading normal n (unit, world space) turned towards n_ref (the unmapped normal, on
// the viewer's side) in the plane the two span, just as far as needed for the mirror
// direction of wo (unit, towards the viewer) about it to leave at least `threshold`
// above n_ref's horizon: threshold = min(0.9 cos_o, 0.01), cos_o = wo.n_ref, so that a
// reflection may always be as shallow as the view, never below it (Cycles'
// ensure_valid_specular_reflection). Returns n itself where its mirror direction is
// already high enough, or where wo is not above n_ref (nothing to bend towards).
//
// A normal map leaning away from the viewer otherwise puts wo below the shading
// hemisphere at grazing views, where every BSDF is 0 (a black rim), or mirrors wo below
// the surface, where the side tests drop the reflection (a dark ring inside each dimple).
//
// The bent normal is n' = nx X + nz n_ref, X the unit part of n orthogonal to n_ref.
// With ix = wo.X and iz = wo.n_ref, the mirror direction r = 2 (n'.wo) n' - wo has
// r.n_ref = 2 nz (nx ix + nz iz) - iz; setting it to t and squaring gives, in u = nz^2,
//   4 a u^2 - 2 b u + c = 0,  a = ix^2 + iz^2,  b = 2 (a + iz t),  c = (iz + t)^2,
// whose root with 2 nx nz ix = t + iz - 2 u iz of the sign of ix (nx >= 0) is the larger
// one for ix < 0 (n leans away from wo) and the smaller one otherwise.
inline Vec3 valid_reflection_normal(Vec3 n_ref, Vec3 wo, Vec3 n) {
    const float iz = dot(wo, n_ref);
    if (!(iz > 0)) return n;
    const float threshold = std::min(0.9f * iz, 0.01f);
    const Vec3 r = n * (2 * dot(n, wo)) - wo;
    if (dot(r, n_ref) >= threshold) return n;
    Vec3 x = n - n_ref * dot(n, n_ref);
    const float len = length(x);
    // n along n_ref (or opposite): its mirror direction is wo's own, above the horizon,
    // unless n is -n_ref; n_ref is the normal to fall back to then.
    if (!(len > 1e-7f)) return n_ref;
    x = x / len;
    const float ix = dot(wo, x);
    const float a = ix * ix + iz * iz;
    const float b = 2 * (a + iz * threshold);
    const float c = (iz + threshold) * (iz + threshold);
    const float root = std::sqrt(std::max(0.0f, b * b - 4 * a * c));
    const float u = std::clamp((ix < 0 ? b + root : b - root) / (4 * a), 0.0f, 1.0f);
    return normalize(x * std::sqrt(1 - u) + n_ref * std::sqrt(u));
}

}  // namespace penumbra
