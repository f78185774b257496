#include "integrators/first_hit.h"

#include "core/camera/camera_culling.h"
#include "integrators/motion_vector.h"

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
        return VisibleSurface{sp, shade(ctx.scene, sp, normalize(-ray.d), ctx.materials), *hit};
    }
    return std::nullopt;
}

AovRecord first_hit_aovs(const Ray& camera_ray, const RenderContext& ctx, uint64_t key,
                         const std::optional<Hit>* first_hit, const FirstVertex* known,
                         const CryptomatteHashes* hashes) {
    FirstVertex v;
    if (first_hit && !*first_hit) return {};  // the packet's ray missed
    if (known && known->valid) {
        v = *known;
    } else {
        Ray ray = camera_ray;
        Rng rng(key);
        const std::optional<VisibleSurface> s =
            first_visible_surface(ray, ctx, rng, true, first_hit);
        if (!s) return {};
        v = {true,          s->sp.p, s->sp.instance, s->sp.material, s->sd.base_color,
             s->sd.frame.n, s->hit};
    }
    AovRecord rec;
    rec.hit = true;
    rec.albedo = v.albedo;
    rec.normal = v.normal;
    rec.position = v.p;
    rec.depth = length(v.p - camera_ray.o);
    rec.object = ctx.scene.instances[v.instance].node;
    rec.material = v.material >= 0 ? v.material : kDefaultMaterialId;
    if (hashes) {
        rec.object_hash = hashes->object(v.instance);
        rec.material_hash = hashes->material(v.material);
    }
    if (ctx.motion_vectors) rec.motion = motion_vector(ctx.scene, *ctx.motion_vectors, v.hit);
    return rec;
}

}  // namespace penumbra
