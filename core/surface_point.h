// The geometry at a hit, in world space, rebuilt from the scene's own mesh data. Every
// accelerator's Hit goes through this one function, so only traversal differs.
#pragma once

#include "core/math/vec.h"
#include "core/ray.h"
#include "core/scene/scene.h"

namespace penumbra {

struct SurfacePoint {
    Vec3 p;        // world position
    Vec3 ng;       // unit geometric normal (from the triangle's winding, as transformed)
    Vec3 ns;       // unit interpolated shading normal, on the same side as ng
    Vec3 dpdu;     // world tangent along texture u (zero when the mesh has no UVs)
    Vec4 tangent;  // world tangent from the mesh (w = bitangent sign); w = 0 when absent
    Vec2 uv0, uv1;
    Vec4 color{1, 1, 1, 1};  // COLOR_0
    float t = 0;
    uint32_t instance = 0, mesh = 0, prim = 0;
    int material = -1;
};

SurfacePoint make_surface_point(const Scene& scene, const Ray& ray, const Hit& hit);

// Origin for a ray leaving p on the side of n that w points to: p pushed along the
// geometric normal by an offset that scales with |p|, so that the new ray does not hit
// the surface it leaves (self-intersection "acne").
Vec3 offset_ray_origin(Vec3 p, Vec3 ng, Vec3 w);

// A ray from p towards a point at distance dist along unit w, stopping short of it.
Ray spawn_ray(const SurfacePoint& sp, Vec3 w, float dist, float time);

}  // namespace penumbra
