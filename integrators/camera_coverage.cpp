#include "integrators/camera_coverage.h"

#include <algorithm>

#include "core/camera/camera_culling.h"
#include "materials/material.h"

namespace penumbra {

float camera_coverage(const Ray& camera_ray, const RenderContext& ctx,
                      const std::optional<Hit>* first_hit) {
    Ray ray = camera_ray;
    float clear = 1;  // the share of the ray that no surface has stopped yet
    // As the integrators do: a bounded number of see-through layers.
    for (int layer = 0; layer <= 256; ++layer) {
        const std::optional<Hit> hit =
            layer == 0 && first_hit ? *first_hit : ctx.accel.intersect(ray);
        if (!hit) break;
        const SurfacePoint sp = make_surface_point(ctx.scene, ray, *hit);
        if (ctx.camera_culling && camera_culls(ctx.scene, sp, ray.d)) {
            pass_culled(sp, ray);
            continue;
        }
        if (!ctx.has_alpha) return 1;
        const float opacity = surface_opacity(ctx.scene, sp);
        if (opacity >= 1) return 1;
        clear *= 1 - std::max(opacity, 0.0f);
        if (!(clear > 0)) return 1;
        // Beyond the surface, as step_through moves the integrators' rays.
        ray.o = offset_ray_origin(sp.p, sp.ng, ray.d);
        ray.tmin = 0;
    }
    return 1 - clear;
}

}  // namespace penumbra
