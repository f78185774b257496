#include "integrators/direct_integrator.h"

#include "core/camera/camera_culling.h"
#include "integrators/direct_lighting.h"

namespace penumbra {

namespace {

// The light sampling and BSDF sampling counts (nl, nb) and the strategy they make:
// with one switched off, the other carries full weight.
struct SampleCounts {
    float nl, nb;
    LightStrategy strategy;
};

SampleCounts sample_counts(const IntegratorOptions& o) {
    SampleCounts c;
    c.nl = static_cast<float>(std::max(0, o.light_samples));
    c.nb = static_cast<float>(std::max(0, o.bsdf_samples));
    c.strategy = c.nb == 0   ? LightStrategy::LightOnly
                 : c.nl == 0 ? LightStrategy::BsdfOnly
                             : LightStrategy::Mis;
    return c;
}

// Emission that the BSDF sample bs's ray finds, MIS-weighted against the light samples,
// through partly covered surfaces as the light samples' shadow rays go (clear: the
// transparency crossed so far), so that both strategies of MIS see an emitter behind a
// sheet alike. medium: the one the ray leaves into (null: none).
Spectrum emission_found(const RenderContext& ctx, const SurfacePoint& sp, const ShadingData& sd,
                        const BsdfSample& bs, Vec3 wi_world, float time, const Medium* medium,
                        const SampleCounts& n) {
    Ray r = spawn_ray(sp, wi_world, std::numeric_limits<float>::infinity(), time);
    Spectrum found(0);
    float clear = 1;
    for (int layer = 0; layer < 256 && clear > 0; ++layer) {
        const std::optional<Hit> h = ctx.accel.intersect(r);
        if (!h) {
            const EnvironmentLight* env = ctx.lights.environment();
            if (!env) break;
            float env_pdf;
            const Spectrum Le = env->Le(wi_world, &env_pdf);
            found += Le * (clear * emission_weight_for_pdf(ctx, env, sp.p, sd.ng, env_pdf, bs.pdf,
                                                           n.strategy, n.nl, n.nb));
            break;
        }
        const SurfacePoint lp = make_surface_point(ctx.scene, r, *h);
        const MaterialDesc& m = ctx.scene.material(lp.material);
        const float coverage = ctx.has_alpha ? surface_opacity(ctx.scene, lp) : 1.0f;
        // Unlit surfaces emit their base colour but are not light-sampled.
        if (m.is_emissive() || m.unlit) {
            // An emitter with alpha sends its coverage's share, as light sampling has it.
            const Spectrum Le = shade(ctx.scene, lp, -wi_world).emission * coverage;
            const Light* light = ctx.lights.triangle_light(h->instance, h->mesh, h->prim);
            const float w = emission_weight(ctx, light, sp.p, sd.ng, &lp.p, wi_world, time, bs.pdf,
                                            n.strategy, n.nl, n.nb);
            const Spectrum tr = medium ? medium->transmittance(r, h->t) : Spectrum(1);
            found += tr * Le * (clear * w);
        }
        clear *= 1 - coverage;
        r.tmin = std::nextafter(h->t, std::numeric_limits<float>::infinity());
    }
    return found;
}

// Adds to L the BSDF samples' estimate of the direct light, times shaded (the
// surface's throughput): the emission they find, MIS-weighted against the light
// samples. They estimate the non-specular lobes only; specular lobes are followed by
// the path. Each sample is added to L as it is taken: a separate sum, added once,
// would round differently.
void add_bsdf_sampled_light(const RenderContext& ctx, const SurfacePoint& sp, const ShadingData& sd,
                            Vec3 wo, float time, Sampler& sampler, int bsdf_samples,
                            const SampleCounts& n, const SideMedia& sides, Spectrum shaded,
                            Spectrum& L) {
    const Bsdf& bsdf = *sd.bsdf.get();
    for (int i = 0; i < bsdf_samples; ++i) {
        const Vec2 u_dir = sampler.get_2d();  // first, as in PathIntegrator::trace
        const float u_lobe = sampler.get_1d();
        const std::optional<BsdfSample> bs = bsdf.sample(wo, u_lobe, u_dir, Transport::Radiance);
        if (!bs || bs->is_specular()) continue;
        const Vec3 wi_world = sd.frame.to_world(bs->wi);
        if ((bs->wi.z > 0) != (dot(wi_world, sd.n_side) > 0)) continue;
        const Medium* medium = bs->wi.z > 0 ? sides.wo_side : sides.far_side;
        const Spectrum found = emission_found(ctx, sp, sd, *bs, wi_world, time, medium, n);
        const Spectrum weight =
            bump_shadowed(sd, bsdf, wo, bs->wi, wi_world, bs->f) * (std::abs(bs->wi.z) / bs->pdf);
        L += shaded * weight * found * (1 / n.nb);
    }
}

// The specular part: one more sample, continued only when it picks a specular lobe;
// its weight F / P(lobe) keeps that unbiased. False: the path ends.
bool follow_specular(const RenderContext& ctx, const SurfacePoint& sp, const ShadingData& sd,
                     Vec3 wo, Sampler& sampler, PathMedia& media, Spectrum& beta, Ray& ray) {
    const Vec2 u_dir = sampler.get_2d();  // first, as in PathIntegrator::trace
    const float u_lobe = sampler.get_1d();
    const std::optional<BsdfSample> specular =
        sd.bsdf.get()->sample(wo, u_lobe, u_dir, Transport::Radiance);
    if (!specular || !specular->is_specular()) return false;
    const Vec3 wi_world = sd.frame.to_world(specular->wi);
    if ((specular->wi.z > 0) != (dot(wi_world, sd.n_side) > 0)) return false;
    beta *= specular->weight();
    if (specular->wi.z < 0)
        cross_surface(ctx, media.stack, sp.material, sd.front_face, int(sp.instance));
    ray = spawn_ray(sp, wi_world, std::numeric_limits<float>::infinity(), ray.time);
    return true;
}

}  // namespace

Spectrum DirectIntegrator::Li(const Ray& camera_ray, const RenderContext& ctx,
                              Sampler& sampler) const {
    const SampleCounts n = sample_counts(m_options);
    Spectrum L(0), beta(1);
    Ray ray = camera_ray;
    int passes = 0;
    PathMedia media;  // camera rays start outside all media
    for (int depth = 0;;) {
        const std::optional<Hit> hit = ctx.accel.intersect(ray);
        // As in the path tracer: escaping rays have left every volume, and so have hits
        // outside a volume's bounds.
        if (hit && !media.stack.empty()) {
            leave_outside(ctx, media.stack, ray.o + ray.d * hit->t);
            beta *= segment_transmittance(ctx, media.stack, ray, hit->t);
            if (is_black(beta)) break;
        }
        if (!hit) {
            const EnvironmentLight* env = ctx.lights.environment();
            // A transparent background hides the environment from camera rays only.
            if (env && (depth > 0 || !m_options.transparent_background))
                L += beta * env->Le(normalize(ray.d));
            break;
        }
        const SurfacePoint sp = make_surface_point(ctx.scene, ray, *hit);
        // Before the first bounce, as in PathIntegrator::trace.
        if (depth == 0 && ctx.camera_culling && camera_culls(ctx.scene, sp, ray.d)) {
            pass_culled(sp, ray);
            if (++passes > 256) break;
            continue;
        }
        const Vec3 wo_world = normalize(-ray.d);
        dispersion_channel(ctx, media, sp.material, sampler, beta);
        const bool front = dot(wo_world, sp.ng) >= 0;  // as shade() decides it
        const ShadingData sd = shade(ctx.scene, sp, wo_world, ctx.materials,
                                     path_volume(ctx, media, sp.material, front));
        const Coverage cover = partial_coverage(sd, sampler);
        if (cover.through && !(cover.share > 0)) {  // a hole: nothing to shade
            step_through(sp, sd, ray);
            if (++passes > 256) break;  // a stack of holes ends the path
            continue;
        }
        // What this surface sends to the camera, weighted by its coverage.
        const Spectrum shaded = beta * cover.share;
        L += shaded * sd.emission;
        const Vec3 wo = sd.frame.to_local(wo_world);
        const SideMedia sides = side_media(ctx, media.stack, sp.material, sd.front_face);
        L += shaded * sample_light_stratified(ctx, sp, sd, wo, ray.time, sampler,
                                              m_options.light_samples, n.strategy, n.nb, sides);
        add_bsdf_sampled_light(ctx, sp, sd, wo, ray.time, sampler, m_options.bsdf_samples, n, sides,
                               shaded, L);
        if (cover.through) {
            step_through(sp, sd, ray);
            if (++passes > 256) break;
            continue;
        }
        if (!sd.bsdf.get()->has_specular() || ++depth >= m_options.max_depth) break;
        if (!follow_specular(ctx, sp, sd, wo, sampler, media, beta, ray)) break;
    }
    return L;
}

}  // namespace penumbra
