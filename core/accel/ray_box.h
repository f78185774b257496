// Ray against axis-aligned box: the slab test with a precomputed inverse direction
// (Williams et al. 2005, "An Efficient and Robust Ray-Box Intersection Algorithm").
// Shared by the BVH nodes, the grid's outer box and the instance level.
#pragma once

#include <cmath>
#include <limits>

#include "core/math/vec.h"
#include "core/ray.h"

namespace penumbra {

// Per-ray data for the slab test, computed once per ray (and once more in each
// instance's object space).
struct RayBoxPrecomp {
    Vec3 o;
    Vec3 inv_d;  // 1/d; a zero component gives +-inf, which the slab test handles
    int neg[3];  // 1 where inv_d < 0 (including d = -0): the near plane is then hi
    float tmin, tmax;
    bool valid;

    explicit RayBoxPrecomp(const Ray& ray) : o(ray.o), tmin(ray.tmin), tmax(ray.tmax) {
        for (int a = 0; a < 3; ++a) {
            inv_d[a] = 1.0f / ray.d[a];
            neg[a] = std::signbit(inv_d[a]) ? 1 : 0;
        }
        // A ray with a NaN or infinite origin or direction, a zero direction or an
        // unordered interval (NaN ends, tmin > tmax) is unusable: it must miss, and it
        // must not visit every node with NaN plane distances (which the slab test below
        // ignores). Its tmin becomes NaN, which fails every comparison in ray_box, so it
        // misses every box whatever tmax the caller passes; traversal checks `valid` and
        // does not even start.
        valid = is_finite(ray.o) && is_finite(ray.d) &&
                (ray.d.x != 0 || ray.d.y != 0 || ray.d.z != 0) && ray.tmin <= ray.tmax;
        if (!valid) tmin = tmax = std::numeric_limits<float>::quiet_NaN();
    }
};

// Slack on the exit distance: the t values of the planes are rounded (one subtraction,
// one multiplication), so a hit exactly on a box face could otherwise be culled. pbrt-v4
// (Bounds3::IntersectP) widens tfar by 1 + 2 gamma(3); gamma(n) = n eps / (1 - n eps).
constexpr float kSlabExitSlack = 1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f);

// Intersects the ray with the box [lo, hi] over [r.tmin, tmax] (the caller passes its
// current closest hit as tmax). Per axis, the entry plane is lo or hi by the sign of the
// direction; the ray is in the box over [last entry, first exit].
//
// NaN handling: an origin exactly on a plane with a zero direction component gives
// 0 * inf = NaN. The comparisons are written so that a NaN plane distance leaves the
// interval unchanged, which treats a ray lying in a face of the box as inside it (the
// box is closed, as Embree's is). Unusable rays carry tmin = NaN and always miss.
// Returns the entry distance in *t_enter.
inline bool ray_box(const float lo[3], const float hi[3], const RayBoxPrecomp& r, float tmax,
                    float* t_enter) {
    float t0 = r.tmin, t1 = tmax;
    for (int a = 0; a < 3; ++a) {
        const float near_plane = r.neg[a] ? hi[a] : lo[a];
        const float far_plane = r.neg[a] ? lo[a] : hi[a];
        const float tn = (near_plane - r.o[a]) * r.inv_d[a];
        const float tf = (far_plane - r.o[a]) * r.inv_d[a] * kSlabExitSlack;
        t0 = tn > t0 ? tn : t0;  // NaN tn: false, t0 kept
        t1 = tf < t1 ? tf : t1;  // NaN tf: false, t1 kept
    }
    *t_enter = t0;
    return t0 <= t1;
}

}  // namespace penumbra
