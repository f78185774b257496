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

namespace {

// The light-sampling estimate for one point u on an already chosen light. Inlined into
// sample_one_light, which runs at every path vertex: a call passing its eleven arguments
// cost about 30 instructions a vertex.
[[gnu::always_inline]] inline Spectrum sample_chosen_light(
    const RenderContext& ctx, const SurfacePoint& sp, const ShadingData& sd, Vec3 wo, float time,
    const SampledLight* chosen, Vec2 u, LightStrategy strategy, float light_samples,
    float bsdf_samples, const SideMedia& media) {
    const Light& light = *chosen->light;
    // Light-sampling estimates of non-delta lights are dropped under BSDF-only.
    if (strategy == LightStrategy::BsdfOnly && !light.is_delta()) return Spectrum(0);
    const ShadingPoint ref{sp.p, sd.ng};
    const std::optional<LightSample> ls = light.sample_Li(ref, u, time);
    if (!ls || !(ls->pdf > 0)) return Spectrum(0);
    const Vec3 wi = sd.frame.to_local(ls->wi);
    // The shading frame and the interpolated normal must agree on the side, or light
    // leaks (spawn_ray then keeps rays the facet's plane puts behind from leaking).
    if ((wi.z > 0) != (dot(ls->wi, side_normal(sp, sd.ng)) > 0)) return Spectrum(0);
    const Bsdf& bsdf = *sd.bsdf.get();
    // The BSDF's density for the MIS weight comes with f where the weight needs it (one
    // pass over the shared terms), so only after the shadow ray is it read.
    const bool weighted = !ls->delta && strategy == LightStrategy::Mis;
    float bsdf_pdf = 0;
    const Spectrum f = (weighted ? bsdf.eval_pdf(wo, wi, Transport::Radiance, &bsdf_pdf)
                                 : bsdf.eval(wo, wi, Transport::Radiance)) *
                       bump_shadowing(side_normal(sp, sd.ng), sd.frame.n, ls->wi);
    if (is_black(f)) return Spectrum(0);
    const Ray shadow = spawn_ray(sp, ls->wi, ls->dist, time);
    const float transparency = shadow_transmittance(ctx, shadow);
    if (!(transparency > 0)) return Spectrum(0);
    Spectrum tr(transparency);
    if (const Medium* medium = wi.z > 0 ? media.wo_side : media.far_side)
        tr *= medium->transmittance(shadow, ls->dist);
    const float light_pdf = chosen->pmf * ls->pdf;
    const float w =
        weighted ? power_heuristic(light_samples, light_pdf, bsdf_samples, bsdf_pdf) : 1.0f;
    return f * tr * ls->Li * (std::abs(wi.z) * w / light_pdf);
}

}  // namespace

Spectrum sample_one_light(const RenderContext& ctx, const SurfacePoint& sp,
                          const ShadingData& sd, Vec3 wo, float time, PathSampler& sampler,
                          LightStrategy strategy, float light_samples, float bsdf_samples,
                          const SideMedia& media) {
    // Where the choice allows it, the light sample's first coordinate chooses the light
    // too (rescaled, as Cycles does): the points on an emitter made of several triangles
    // (the Cornell box's two-triangle panel) then stay stratified over all of it, not
    // over each triangle apart; direct light's relMSE there fell 30% at 64 spp
    // (docs/performance.md). u_light is drawn in every case, so that the sampler's
    // dimensions do not depend on the light sampler (deferred: a remapping choice does
    // not read it).
    const PathSampler::Deferred1d u_light = sampler.defer_1d();
    const Vec2 u = sampler.get_2d();
    // The remapped coordinate goes to its own float: written through a pointer into u
    // and read back as the whole Vec2, it stalled on store forwarding (a third of this
    // function's time in the profile).
    float u_x = u.x;
    const std::optional<SampledLight> chosen =
        ctx.lights.remaps_choice()
            ? ctx.lights.sample_remapped(u.x, &u_x)
            : ctx.lights.sample(ShadingPoint{sp.p, sd.ng}, sampler.value(u_light));
    if (!chosen) return Spectrum(0);
    return sample_chosen_light(ctx, sp, sd, wo, time, &*chosen,
                               Vec2(u_x, u.y), strategy, light_samples, bsdf_samples, media);
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
    for (int i = 0; i < n; ++i) {
        const Vec2 jitter = sampler.get_2d();
        const Vec2 u(std::min((i + jitter.x) * inv_n, 0x1.fffffep-1f),
                     std::min((perm[i] + jitter.y) * inv_n, 0x1.fffffep-1f));
        sum += sample_chosen_light(ctx, sp, sd, wo, time, &*chosen, u, strategy,
                                   float(n), bsdf_samples, media);
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
