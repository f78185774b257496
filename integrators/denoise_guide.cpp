#include "integrators/denoise_guide.h"

#include "integrators/direct_lighting.h"
#include "integrators/first_hit.h"

namespace penumbra {

namespace {

// Whether one light sample from the surface is unoccluded: its shadow ray's
// transmittance (through alpha-blended surfaces as the path tracer's), 0 for a light
// behind the surface or none at all.
float light_visibility(const RenderContext& ctx, const SurfacePoint& sp, const ShadingData& sd,
                       float time, Rng& rng) {
    const ShadingPoint ref{sp.p, sd.ng};
    // Written out so every compiler draws the same.
    const float u_choice = rng.next_float();
    const float u0 = rng.next_float();
    const Vec2 u(u0, rng.next_float());
    const std::optional<SampledLight> chosen = ctx.lights.sample(ref, u_choice);
    if (!chosen) return 0;
    const std::optional<LightSample> ls = sample_light_Li(*chosen->light, ref, u, time);
    if (!ls || !(ls->pdf > 0) || !(dot(ls->wi, sd.n_side) > 0)) return 0;
    return shadow_transmittance(ctx, spawn_ray_to(RayOrigins(sp), ls->wi, ls->dist, ls->p, time));
}

}  // namespace

GuideRecord denoise_guide(const Ray& camera_ray, const RenderContext& ctx, uint64_t key,
                          const std::optional<Hit>* first_hit) {
    GuideRecord rec;
    Ray ray = camera_ray;
    // The same key as first_hit_aovs': with both, they pass the same alpha surfaces.
    Rng rng(key);
    Spectrum throughput(1);
    Vec3 from = camera_ray.o;
    float depth = 0;
    for (int bounce = 0;; ++bounce) {
        const std::optional<VisibleSurface> s =
            first_visible_surface(ray, ctx, rng, bounce == 0, bounce == 0 ? first_hit : nullptr);
        if (!s) return rec;
        const SurfacePoint& sp = s->sp;
        const ShadingData& sd = s->sd;
        depth += length(sp.p - from);
        from = sp.p;
        const Bsdf* bsdf = sd.bsdf.get();
        if (bounce < kMaxGuideBounces && bsdf && bsdf->has_specular()) {
            // The lobe, then the direction: written out so every compiler draws the same.
            const float u_lobe = rng.next_float();
            const float u0 = rng.next_float();
            const Vec2 u(u0, rng.next_float());
            const Vec3 wo = sd.frame.to_local(normalize(-ray.d));
            const std::optional<BsdfSample> bs = bsdf->sample(wo, u_lobe, u, Transport::Importance);
            // A delta lobe the path tracer would follow: on the side its lobe says.
            if (bs && bs->is_specular() && bs->pdf > 0) {
                const Vec3 wi = sd.frame.to_world(bs->wi);
                if ((bs->wi.z > 0) == (dot(wi, sd.n_side) > 0)) {
                    throughput *= bs->weight();
                    ray.cone = bounce_cone(ray.cone, sp.cone_width, bs->pdf, true);
                    continue_ray(ray, RayOrigins(sp), wi);
                    continue;
                }
            }
        }
        rec.albedo = throughput * sd.base_color;
        rec.normal = sd.frame.n;
        rec.depth = depth;
        rec.visibility = light_visibility(ctx, sp, sd, camera_ray.time, rng);
        return rec;
    }
}

}  // namespace penumbra
