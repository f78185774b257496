#include "integrators/first_hit.h"

#include "core/sampling/rng.h"
#include "core/surface_point.h"
#include "materials/material.h"

namespace penumbra {

AovRecord first_hit_aovs(const Ray& camera_ray, const RenderContext& ctx, uint64_t key) {
    AovRecord rec;
    Ray ray = camera_ray;
    Rng rng(key);
    // As the path integrator does: a bounded number of see-through layers.
    for (int layer = 0; layer <= 256; ++layer) {
        const std::optional<Hit> hit = ctx.accel.intersect(ray);
        if (!hit) return rec;
        const SurfacePoint sp = make_surface_point(ctx.scene, ray, *hit);
        const Vec3 wo = normalize(-ray.d);
        if (ctx.has_alpha) {
            const float opacity = surface_opacity(ctx.scene, sp);
            if (opacity < 1 && (opacity <= 0 || rng.next_float() >= opacity)) {
                ray.o = offset_ray_origin(sp.p, sp.ng, ray.d);
                ray.tmin = 0;
                continue;
            }
        }
        const ShadingData sd = shade(ctx.scene, sp, wo, ctx.materials);
        rec.hit = true;
        rec.albedo = sd.base_color;
        rec.normal = sd.frame.n;
        rec.position = sp.p;
        rec.depth = length(sp.p - camera_ray.o);
        return rec;
    }
    return rec;
}

}  // namespace penumbra
