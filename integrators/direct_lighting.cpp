#include "integrators/direct_lighting.h"

#include <algorithm>
#include <cstring>
#include <vector>

#include "core/sampling/rng.h"

namespace penumbra {

void step_through(const SurfacePoint& sp, const ShadingData& sd, Ray& ray) {
    ray.o = offset_ray_origin(sp.p, sd.ng, ray.d);
    ray.tmin = 0;
    ray.cone.width = sp.cone_width;  // the cone goes on from the hit
}

Coverage partial_coverage(const ShadingData& sd, Sampler& sampler) {
    if (sd.opacity >= 1) return {};
    if (!(sd.opacity > 0)) return {0, true};
    return {sd.opacity, sampler.get_1d() >= sd.opacity};
}

float shadow_transmittance_through(const RenderContext& ctx, const Ray& shadow) {
    // Walk through surfaces that let light through, multiplying their transparency:
    // the expectation of the camera paths' stochastic alpha, without its coin flips
    // (Cycles' transparent shadows). Behind a lens of alpha 0.4 a coin flip makes
    // each shadow ray 0 or 1, variance 0.24 where this has none.
    Ray ray = shadow;
    float transmittance = 1;
    for (int guard = 0; guard < 256; ++guard) {
        const std::optional<Hit> hit = ctx.accel.intersect(ray);
        if (!hit) return transmittance;
        const SurfacePoint sp = make_surface_point(ctx.scene, ray, *hit);
        transmittance *= 1 - surface_opacity(ctx.scene, sp);
        if (!(transmittance > 0)) return 0;
        // Continue beyond this surface; tmin just past its t keeps progress monotone.
        ray.tmin = std::nextafter(hit->t, std::numeric_limits<float>::infinity());
    }
    return 0;
}

Spectrum sample_light_stratified(const RenderContext& ctx, const SurfacePoint& sp,
                                 const ShadingData& sd, Vec3 wo, float time, Sampler& sampler,
                                 int n, LightStrategy strategy, float bsdf_samples,
                                 const SideMedia& media) {
    if (n <= 0) return Spectrum(0);
    const std::optional<SampledLight> chosen =
        ctx.lights.sample(ShadingPoint{sp.p, sd.ng}, sampler.get_1d());
    // Latin hypercube over the light's sample square: sample i takes column i and row
    // perm[i], jittered inside, so the n points cover the light evenly in both
    // directions while each, alone, is uniform (the estimator stays unbiased and its MIS
    // weights those of n independent samples). The permutation comes from one sampler
    // dimension, so it is a function of (seed, pixel, sample index) like everything else.
    const float u_perm = sampler.get_1d();
    if (!chosen) return Spectrum(0);
    std::vector<uint32_t> perm(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) perm[i] = static_cast<uint32_t>(i);
    uint32_t bits;
    std::memcpy(&bits, &u_perm, sizeof bits);
    Rng rng(bits);
    for (int i = n - 1; i > 0; --i) std::swap(perm[i], perm[rng.next_below(uint32_t(i + 1))]);
    Spectrum sum(0);
    const float inv_n = 1.0f / n;
    const RayOrigins origins(sp);  // the n shadow rays share them
    for (int i = 0; i < n; ++i) {
        const Vec2 jitter = sampler.get_2d();
        const Vec2 u(std::min((i + jitter.x) * inv_n, 0x1.fffffep-1f),
                     std::min((perm[i] + jitter.y) * inv_n, 0x1.fffffep-1f));
        sum += sample_chosen_light(ctx, origins, sd, wo, time, &*chosen, u, strategy, float(n),
                                   bsdf_samples, media);
    }
    return sum * inv_n;
}

float emission_weight(const RenderContext& ctx, const Light* light, Vec3 prev_p, Vec3 prev_n,
                      const Vec3* hit_p, Vec3 wi, float time, float bsdf_pdf,
                      LightStrategy strategy, float light_samples, float bsdf_samples) {
    if (strategy == LightStrategy::BsdfOnly) return 1;
    if (strategy == LightStrategy::LightOnly) return 0;
    if (!light) return 1;  // emitter the light set does not sample
    // The same receiver as the light sample at prev_p had: the BVH's choice and the
    // cosine warp of spherical triangles both depend on its normal.
    const ShadingPoint ref{prev_p, prev_n};
    float light_pdf;
    if (hit_p)
        light_pdf = static_cast<const TriangleLight*>(light)->pdf_at(ref, *hit_p, time);
    else
        light_pdf = light->pdf_Li(ref, wi, time);
    return emission_weight_for_pdf(ctx, light, prev_p, prev_n, light_pdf, bsdf_pdf, strategy,
                                   light_samples, bsdf_samples);
}

float emission_weight_for_pdf(const RenderContext& ctx, const Light* light, Vec3 prev_p,
                              Vec3 prev_n, float light_pdf, float bsdf_pdf,
                              LightStrategy strategy, float light_samples, float bsdf_samples) {
    if (strategy == LightStrategy::BsdfOnly) return 1;
    if (strategy == LightStrategy::LightOnly) return 0;
    if (!light) return 1;
    light_pdf *= ctx.lights.pmf(ShadingPoint{prev_p, prev_n}, light);
    return power_heuristic(bsdf_samples, bsdf_pdf, light_samples, light_pdf);
}

}  // namespace penumbra
