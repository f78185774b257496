// The geometry at a hit, in world space, rebuilt from the scene's own mesh data. Every
// accelerator's Hit goes through this one function, so only traversal differs.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/math/next_float.h"
#include "core/math/vec.h"
#include "core/ray.h"
#include "core/scene/scene.h"

namespace penumbra {

struct SurfacePoint {
    Vec3 p;        // world position
    // p lifted onto the smooth surface the vertex normals imply (Hanika 2021, "Hacking
    // the shadow terminator"): the origin of rays that leave on the normals' side, so
    // that coarse meshes with smooth normals do not shadow themselves facet by facet.
    // Equal to p for flat meshes and concave spots.
    Vec3 p_smooth;
    // Per-axis bound on the rounding error in p (and p_smooth) from interpolating the
    // vertices and transforming to world space (pbrt-v4, section 6.8): how far
    // secondary rays must start from the surface.
    Vec3 p_error;
    Vec3 ng;       // unit geometric normal (from the triangle's winding, as transformed)
    // ng points out of the glTF front face (counter-clockwise winding, clockwise under a
    // mirroring transform; glTF 2.0, 3.7.2.1); false where the shading normals turned ng
    // over. Single-sided emitters emit on the front side only (front_normal).
    bool ng_is_front = true;
    Vec3 ns;       // unit interpolated shading normal, on the same side as ng
    Vec3 dpdu;     // world tangent along texture u (zero when the mesh has no UVs)
    Vec4 tangent;  // world tangent from the mesh (w = bitangent sign); w = 0 when absent
    Vec2 uv0, uv1;
    // The ray cone's footprint here: its world width, and that width over the cosine as a
    // width in each UV set (Akenine-Moller et al. 2021, eq. 34); 0 without a cone.
    float cone_width = 0;
    float uv_width[2] = {0, 0};
    Vec4 color{1, 1, 1, 1};  // COLOR_0
    float t = 0;
    uint32_t instance = 0, mesh = 0, prim = 0;
    int material = -1;
};

SurfacePoint make_surface_point(const Scene& scene, const Ray& ray, const Hit& hit);

// Hanika's lifted point in object space: the barycentric mix of p projected onto each
// vertex's tangent plane, where p lies below it (min(0, .) keeps concave spots as
// they are). n0..n2 need not be unit length; zero ones leave p as it is.
Vec3 smooth_surface_point(Vec3 p, const Vec3 v[3], const Vec3 n[3], const float b[3]);

// Bounds on float rounding (pbrt-v4, section 6.8.1): n operations, unit roundoff u.
constexpr float rounding_gamma(int n) {
    constexpr float u = std::numeric_limits<float>::epsilon() * 0.5f;
    return n * u / (1 - n * u);
}

// Origin for a ray leaving p on the side of n that w points to: p pushed along the
// geometric normal by an offset that scales with |p|, so that the new ray does not hit
// the surface it leaves (self-intersection "acne").
Vec3 offset_ray_origin(Vec3 p, Vec3 ng, Vec3 w);

// p moved along `side` (the unit normal n or -n, towards where the ray leaves), just past
// the error box p_error (times a safety factor of 4), then rounded away from p (pbrt-v4's
// OffsetRayOrigin, which picks the side from a direction w by dot(w, n): ray_origin knows
// it without one): a ray from there cannot hit the surface it leaves, and the offset is a
// few ULPs of the coordinates along n only, so contact shadows stay put far from the
// origin.
inline Vec3 offset_ray_origin_along(Vec3 p, Vec3 p_error, Vec3 side) {
    // Safety factor 4: the accelerators move the origin into instance space, which
    // rounds about as much again as p_error covers. The error bound is 0 along an axis
    // where every term is 0 (a plane y = 0), but the accelerators' arithmetic is not
    // exact: never less than gamma(3) of the largest coordinate (about 1.5 ULPs), nor a
    // tiny absolute floor.
    const float scale = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    const float spread = std::abs(side.x) * p_error.x + std::abs(side.y) * p_error.y +
                         std::abs(side.z) * p_error.z;  // dot(|n|, p_error)
    const float d = 4 * std::max({spread, rounding_gamma(3) * scale, 1e-20f});
    Vec3 po = p + side * d;
    // The addition rounds too: step each coordinate one float further along the normal.
    for (int i = 0; i < 3; ++i) {
        if (side[i] > 0) po[i] = next_float_up(po[i]);
        else if (side[i] < 0) po[i] = next_float_down(po[i]);
    }
    return po;
}

// The origin of the rays that leave sp on one side: p_smooth pushed off along ng on the
// side of ns ("outside"), p along -ng on the other (offset_ray_origin_along).
inline Vec3 ray_origin(const SurfacePoint& sp, bool outside) {
    return outside ? offset_ray_origin_along(sp.p_smooth, sp.p_error, sp.ng)
                   : offset_ray_origin_along(sp.p, sp.p_error, -sp.ng);
}

// The side a ray in direction w leaves sp on. It is decided by the interpolated normal
// sp.ns (as the file gives it, with sp.ng turned to its side), as the integrators' side
// tests are: a ray the facet's plane puts on the other side then starts above the facet
// and is stopped by it unless the lifted origin clears the facet (a convex coarse
// mesh), so it cannot leak through a sheet.
inline bool leaves_outside(const SurfacePoint& sp, Vec3 w) { return dot(w, sp.ns) > 0; }

// A path vertex's ray origins. Its light sample and its continuation leave from the
// same origin whenever both leave outside (every reflection), and the offset costs
// about 90 instructions: so the outside origin is computed once, up front, and the
// inside one, which only transmission and grazing samples take, at each use.
class RayOrigins {
public:
    explicit RayOrigins(const SurfacePoint& sp) : m_sp(sp), m_outside(ray_origin(sp, true)) {}
    Vec3 for_direction(Vec3 w) const {
        return leaves_outside(m_sp, w) ? m_outside : ray_origin(m_sp, false);
    }
    const SurfacePoint& point() const { return m_sp; }

private:
    const SurfacePoint& m_sp;
    Vec3 m_outside;
};

// A ray from origin o (ray_origin's for the side w leaves the surface on) along unit w; where
// dist is finite, towards `target` (the point at distance dist along w), stopping short
// of it. Inline, as offset_ray_origin: the caller reads the ray at once, and inline it stays
// in registers instead of being read back from memory with 16-byte loads of 4-byte stores.
inline Ray spawn_ray_from(Vec3 o, Vec3 w, float dist, Vec3 target, float time) {
    Ray r;
    r.o = o;
    r.d = w;
    r.tmin = 0;
    r.tmax = std::numeric_limits<float>::infinity();
    if (std::isfinite(dist)) {
        // A shadow ray to a point: aimed from the moved origin at the point itself
        // (pbrt-v4's SpawnRayTo). Kept parallel to w, a lifted origin would carry the
        // segment's end past the point, into the area light sampled there, which then
        // blocks its own light (a smooth sphere under a panel loses 60% of its direct light).
        const Vec3 to = target - r.o;
        const float len = length(to);
        r.d = len > 0 ? to / len : w;
        r.tmax = len * (1 - 1e-4f);
    }
    r.time = time;
    return r;
}

// A ray from sp (p_smooth when w leaves on the side of ns) towards the point at distance
// dist along unit w, stopping short of it.
inline Ray spawn_ray(const SurfacePoint& sp, Vec3 w, float dist, float time) {
    return spawn_ray_from(ray_origin(sp, leaves_outside(sp, w)), w, dist, sp.p + w * dist, time);
}

// A shadow ray from the vertex (its origins) to `target`, the point at distance dist
// along unit w that the light sample gives (LightSample::p): the same ray up to the
// rounding of sp.p + w * dist, with a shorter chain of dependent operations.
inline Ray spawn_ray_to(const RayOrigins& origins, Vec3 w, float dist, Vec3 target, float time) {
    return spawn_ray_from(origins.for_direction(w), w, dist, target, time);
}

// A path's ray turned into its continuation from the vertex along unit w: spawn_ray with
// an infinite distance, its time and cone left as they are. Written field by field into
// the ray: `ray = spawn_ray(...)` builds a temporary and copies it over with 16-byte loads
// of its 4- and 8-byte stores, which wait for those stores at every bounce.
inline void continue_ray(Ray& ray, const RayOrigins& origins, Vec3 w) {
    ray.o = origins.for_direction(w);
    ray.d = w;
    ray.tmin = 0;
    ray.tmax = std::numeric_limits<float>::infinity();
}

// The normal that decides on which side of the surface a direction lies (light and
// BSDF samples whose lobe side disagrees with it are dropped): the interpolated normal
// sp.ns turned to the side of n_side (the geometric normal on the viewer's side). With
// spawn_ray's lifted origins this gives a smooth shadow terminator on coarse meshes.
inline Vec3 side_normal(const SurfacePoint& sp, Vec3 n_side) {
    return dot(sp.ns, n_side) < 0 ? -sp.ns : sp.ns;
}

// The unit geometric normal on the glTF front side of the triangle (see ng_is_front).
inline Vec3 front_normal(const SurfacePoint& sp) { return sp.ng_is_front ? sp.ng : -sp.ng; }

}  // namespace penumbra
