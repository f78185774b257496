// What a light BVH node knows about the lights below it: where they are (a box), how much
// they emit (phi), and which way (a cone of normals w, theta_o, plus the spread theta_e
// of emission about each normal), after Conty Estevez & Kulla 2018 and pbrt-v4's
// LightBounds. importance() is an upper-bound-shaped estimate of their contribution.
#pragma once

#include "core/math/vec.h"

namespace penumbra {

struct LightBounds {
    Vec3 lo{0}, hi{0};       // world-space box
    float phi = 0;           // power (luminance), the same units as Light::power()
    Vec3 w{0, 0, 1};         // cone axis (unit)
    float cos_theta_o = 1;   // cone of normals (or of spot axes)
    float cos_theta_e = 0;   // emission spread about a normal: pi/2 for a Lambertian side
    bool two_sided = false;  // emits about -w as well as w

    Vec3 centroid() const { return (lo + hi) * 0.5f; }
    // Importance for a receiver at p with normal n (zero n: a point in a medium, no
    // cosine there). Zero only where no light inside can send light to p: behind every
    // single-sided emitter, outside every spot cone (Conty Estevez & Kulla 2018, eq. 3,
    // with pbrt-v4's bound of theta_b, the box seen from p).
    float importance(Vec3 p, Vec3 n) const;
};

// The bounds of both (phi added, cones merged, the wider spread kept).
LightBounds merge(const LightBounds& a, const LightBounds& b);

}  // namespace penumbra
