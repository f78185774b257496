// Back-face culling for the camera: camera rays see a single-sided (doubleSided false)
// surface from its glTF front only, as glTF viewers rasterise it, and pass through its back
// as through an alpha hole. Light paths see both sides (docs/conventions.md).
#pragma once

#include "core/ray.h"
#include "core/scene/scene.h"
#include "core/surface_point.h"

namespace penumbra {

// Whether a camera ray along d passes through the surface at sp: its material is
// single-sided and d meets the back of its glTF front face (front_normal: the winding's,
// flipped under a mirroring instance, whatever the shading normals say). The test reads
// only the surface point, which our own code rebuilds from the hit, so every accelerator
// culls the same hits. A ray exactly in the plane is not culled.
inline bool camera_culls(const Scene& scene, const SurfacePoint& sp, Vec3 d) {
    return dot(d, front_normal(sp)) > 0 && !scene.material(sp.material).double_sided;
}

// Moves the camera ray on beyond the culled surface at sp, as step_through does for an
// alpha hole, from just past the hit's error bound on the far side.
inline void pass_culled(const SurfacePoint& sp, Ray& ray) {
    ray.o = offset_ray_origin_along(sp.p, sp.p_error, dot(ray.d, sp.ng) > 0 ? sp.ng : -sp.ng);
    ray.tmin = 0;
    ray.cone.width = sp.cone_width;  // the cone goes on from the hit
}

}  // namespace penumbra
