#include "integrators/basic_integrator.h"

#include "core/camera/camera_culling.h"
#include "core/surface_point.h"
#include "integrators/direct_lighting.h"
#include "materials/material.h"

namespace penumbra {

Spectrum BasicIntegrator::Li(const Ray& camera_ray, const RenderContext& ctx,
                             Sampler& sampler) const {
    const Scene& scene = ctx.scene;
    const Accel& accel = ctx.accel;
    Spectrum L(0), throughput(1);
    Ray ray = camera_ray;
    int passes = 0;
    for (int depth = 0;;) {
        const std::optional<Hit> hit = accel.intersect(ray);
        if (!hit) {
            const EnvironmentLight* env = ctx.lights.environment();
            // A transparent background hides the environment from camera rays only.
            if (env && (depth > 0 || !m_options.transparent_background))
                L += throughput * env->Le(normalize(ray.d));
            break;
        }
        const SurfacePoint sp = make_surface_point(scene, ray, *hit);
        // Before the first bounce, as in PathIntegrator::trace.
        if (depth == 0 && ctx.camera_culling && camera_culls(scene, sp, ray.d)) {
            pass_culled(sp, ray);
            if (++passes > 256) break;
            continue;
        }
        const Vec3 wo_world = normalize(-ray.d);
        const ShadingData sd = shade(scene, sp, wo_world, ctx.materials);
        // Alpha coverage as in the other integrators (direct_lighting.h).
        const Coverage cover = partial_coverage(sd, sampler);
        if (cover.through && !(cover.share > 0)) {  // a hole: nothing to shade
            step_through(sp, sd, ray);
            if (++passes > 256) break;
            continue;
        }
        const Spectrum shaded = throughput * cover.share;
        const Bsdf* bsdf = sd.bsdf.get();
        const Vec3 wo = sd.frame.to_local(wo_world);
        L += shaded * sd.emission;

        // Direct light: one shadow ray per punctual light.
        const ShadingPoint ref{sp.p, sd.ng};
        for (const auto& light : scene.lights) {
            const std::optional<LightSample> ls = light->sample_Li(ref, sampler.get_2d(), ray.time);
            if (!ls || dot(ls->wi, sd.n_side) <= 0) continue;
            const Vec3 wi = sd.frame.to_local(ls->wi);
            const Spectrum f =
                bump_shadowed(sd, *bsdf, wo, wi, ls->wi, bsdf->eval(wo, wi, Transport::Radiance));
            if (is_black(f)) continue;
            const float transparency = shadow_transmittance(
                ctx, spawn_ray_to(RayOrigins(sp), ls->wi, ls->dist, ls->p, ray.time));
            if (!(transparency > 0)) continue;
            L += shaded * f * ls->Li * (transparency * std::abs(wi.z) / ls->pdf);
        }
        if (cover.through) {
            step_through(sp, sd, ray);
            if (++passes > 256) break;
            continue;
        }

        // Perfect specular reflection only; other lobes end the path.
        if (++depth >= m_options.max_depth || !bsdf->has_specular()) break;
        const Vec2 u_dir = sampler.get_2d();  // first, as in PathIntegrator::trace
        const float u_lobe = sampler.get_1d();
        const std::optional<BsdfSample> bs = bsdf->sample(wo, u_lobe, u_dir, Transport::Radiance);
        if (!bs || !bs->is_specular()) break;
        const Vec3 wi_world = sd.frame.to_world(bs->wi);
        if (dot(wi_world, sd.n_side) <= 0) break;
        throughput *= bs->weight();
        if (is_black(throughput)) break;
        ray = spawn_ray(sp, wi_world, std::numeric_limits<float>::infinity(), ray.time);
    }
    return L;
}

}  // namespace penumbra
