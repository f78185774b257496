#include "integrators/first_hit.h"

#include "core/camera/camera_culling.h"
#include "core/film/cryptomatte.h"

namespace penumbra {

std::optional<VisibleSurface> first_visible_surface(Ray& ray, const RenderContext& ctx, Rng& rng,
                                                    bool camera,
                                                    const std::optional<Hit>* first_hit) {
    // As the path integrator does: a bounded number of see-through layers.
    for (int layer = 0; layer <= 256; ++layer) {
        const std::optional<Hit> hit =
            layer == 0 && first_hit ? *first_hit : ctx.accel.intersect(ray);
        if (!hit) return std::nullopt;
        const SurfacePoint sp = make_surface_point(ctx.scene, ray, *hit);
        if (camera && ctx.camera_culling && camera_culls(ctx.scene, sp, ray.d)) {
            pass_culled(sp, ray);
            continue;
        }
        if (ctx.has_alpha) {
            const float opacity = surface_opacity(ctx.scene, sp);
            if (opacity < 1 && (opacity <= 0 || rng.next_float() >= opacity)) {
                ray.o = offset_ray_origin(sp.p, sp.ng, ray.d);
                ray.tmin = 0;
                continue;
            }
        }
        return VisibleSurface{sp, shade(ctx.scene, sp, normalize(-ray.d), ctx.materials)};
    }
    return std::nullopt;
}

AovRecord first_hit_aovs(const Ray& camera_ray, const RenderContext& ctx, uint64_t key,
                         const std::optional<Hit>* first_hit) {
    AovRecord rec;
    Ray ray = camera_ray;
    Rng rng(key);
    const std::optional<VisibleSurface> s = first_visible_surface(ray, ctx, rng, true, first_hit);
    if (!s) return rec;
    rec.hit = true;
    rec.albedo = s->sd.base_color;
    rec.normal = s->sd.frame.n;
    rec.position = s->sp.p;
    rec.depth = length(s->sp.p - camera_ray.o);
    rec.object = ctx.scene.instances[s->sp.instance].node;
    rec.material = s->sp.material >= 0 ? s->sp.material : kDefaultMaterialId;
    rec.object_hash = cryptomatte_hash(cryptomatte_object_name(ctx.scene, s->sp.instance));
    rec.material_hash = cryptomatte_hash(cryptomatte_material_name(ctx.scene, s->sp.material));
    return rec;
}

}  // namespace penumbra
