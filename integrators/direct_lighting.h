// Next-event estimation and multiple importance sampling shared by the path and direct
// integrators (like Tungsten's TraceBase): light sampling, shadow rays through
// alpha-blended surfaces, and the power heuristic.
#pragma once

#include <algorithm>

#include "core/lights/point_light.h"
#include "core/sampling/path_sampler.h"
#include "core/surface_point.h"
#include "integrators/integrator.h"
#include "integrators/path_media.h"
#include "materials/bsdf_calls.h"
#include "materials/material.h"

namespace penumbra {

// Veach's power heuristic (beta = 2) for nf samples of density f_pdf against ng of g_pdf.
inline float power_heuristic(float nf, float f_pdf, float ng, float g_pdf) {
    const float f = nf * f_pdf, g = ng * g_pdf;
    if (std::isinf(f * f)) return 1;
    const float denom = f * f + g * g;
    return denom > 0 ? (f * f) / denom : 0.0f;
}

// The bump terminator fix (Chiang, Li, Burley 2019, "Taming the Shadow Terminator", as
// Cycles' bump_shadowing_term): diffuse light at wi on a normal-mapped surface is scaled
// by G = min(1, <n_s, wi> / (<n_b, wi> <n_s, n_b>)), smoothed to -G^3 + G^2 + G, with n_s
// the unperturbed (interpolated) normal and n_b the mapped one, both on the viewer's
// side. Without a normal map n_b = n_s and this is exactly 1. Transmitted light (wi below
// n_b) is left alone. (Conty Estevez et al. 2019, Ray Tracing Gems ch. 12, derive a
// GGX-style G1 for the same purpose instead.)
inline float bump_shadowing(Vec3 n_smooth, Vec3 n_bump, Vec3 wi) {
    // What the formula gives then (a division and three dot products at every light
    // and BSDF sample of a surface without a normal map).
    if (n_smooth == n_bump) return 1;
    const float nb_wi = dot(n_bump, wi), cos_d = dot(n_smooth, n_bump);
    if (!(nb_wi > 0) || !(cos_d > 0)) return 1;
    const float g = std::min(1.0f, std::max(0.0f, dot(n_smooth, wi)) / (nb_wi * cos_d));
    // The smoothed curve is flat at 1 (1 - 2 (1 - g)^2): snapping the last 1e-4 costs
    // under 2e-8 and keeps unmapped surfaces exactly as they were.
    return g > 1 - 1e-4f ? 1.0f : g * (1 + g - g * g);
}

// bump_shadowing at a hit, for light arriving along wi: exactly 1 without a normal map,
// as the formula gives it, without its comparison of the normals at each sample.
inline float bump_shadowing(const ShadingData& sd, Vec3 wi) {
    return sd.bumped ? bump_shadowing(sd.n_side, sd.frame.n, wi) : 1.0f;
}

// f = bsdf.eval(wo, wi) (local; wi_world the same direction in world space) with
// bump_shadowing on its diffuse lobes only (Bsdf::eval_diffuse), as Cycles applies it to
// diffuse closures only. The term fades diffuse light smoothly at a normal-mapped
// terminator; on a glossy or mirror lobe it would take most of every reflection a steep bump
// turns towards the horizon (under a white sky, a black ring around each bump of a
// mirror-smooth normal map), light that the neighbouring bumps pass on, not block.
inline Spectrum bump_shadowed(const ShadingData& sd, const Bsdf& bsdf, Vec3 wo, Vec3 wi,
                              Vec3 wi_world, Spectrum f) {
    if (!sd.bumped) return f;
    const float g = bump_shadowing(sd.n_side, sd.frame.n, wi_world);
    if (!(g < 1)) return f;
    const Spectrum fd = bsdf.is_lambertian() ? f : bsdf.eval_diffuse(wo, wi, Transport::Radiance);
    return max(f - fd * (1 - g), Spectrum(0));
}

// Partial coverage (glTF alpha MASK/BLEND) at a path's hit. The surface's share of the
// light, its coverage, is shaded there as a weight, and the path goes on straight through
// with probability 1 - coverage, else as the surface sends it; the throughput is
// unchanged either way, the probabilities cancelling the shares (Cycles' transparent
// closure). Flipping the coin first and shading all or nothing left FlightHelmet's lenses
// as noisy as the coin. Draws a sample only for 0 < coverage < 1.
struct Coverage {
    float share = 1;       // 1 opaque, 0 a hole (nothing to shade), else partial
    bool through = false;  // the path goes on beyond the surface (step_through)
};
Coverage partial_coverage(const ShadingData& sd, Sampler& sampler);

// Moves `ray` on beyond the surface at sp, as if the surface were not there.
void step_through(const SurfacePoint& sp, const ShadingData& sd, Ray& ray);

// shadow_transmittance in a scene with partial coverage: the walk through its surfaces.
float shadow_transmittance_through(const RenderContext& ctx, const Ray& shadow);

// The share of light that the segment `shadow` carries to its tmax: 0 when an opaque
// surface blocks it, else the product of (1 - opacity) over the partly covered (alpha)
// surfaces it crosses. Inline: without partial coverage it is one occlusion query, and
// every light sample asks it.
inline float shadow_transmittance(const RenderContext& ctx, const Ray& shadow) {
    // By reference: a copy of the ray spawn_ray just wrote would wait for its stores.
    if (!ctx.has_alpha) return ctx.accel.occluded(shadow) ? 0.0f : 1.0f;
    return shadow_transmittance_through(ctx, shadow);
}

// The light-sampling estimate for one point u on an already chosen light. Inlined into
// sample_one_light and sample_light_stratified: a call passing its eleven arguments costs
// about 30 instructions a vertex.
[[gnu::always_inline]] inline Spectrum sample_chosen_light(
    const RenderContext& ctx, const RayOrigins& origins, const ShadingData& sd, Vec3 wo, float time,
    const SampledLight* chosen, Vec2 u, LightStrategy strategy, float light_samples,
    float bsdf_samples, const SideMedia& media) {
    const SurfacePoint& sp = origins.point();
    const Light& light = *chosen->light;
    // Light-sampling estimates of non-delta lights are dropped under BSDF-only.
    if (strategy == LightStrategy::BsdfOnly && !light.is_delta()) return Spectrum(0);
    const ShadingPoint ref{sp.p, sd.ng};
    const std::optional<LightSample> ls = sample_light_Li(light, ref, u, time);
    if (!ls || !(ls->pdf > 0)) return Spectrum(0);
    const Bsdf& bsdf = *sd.bsdf.get();
    const Vec3 wi = to_bsdf_local(bsdf, sd.frame, ls->wi);
    // The shading frame and the interpolated normal must agree on the side, or light
    // leaks (spawn_ray then keeps rays the facet's plane puts behind from leaking). Without
    // a normal map n_side is frame.n (ShadingData::bumped) and wi.z is dot(ls->wi,
    // frame.n) (to_bsdf_local): they agree by construction, so the dot is skipped.
    if (sd.bumped && (wi.z > 0) != (dot(ls->wi, sd.n_side) > 0)) return Spectrum(0);
    // The BSDF's density for the MIS weight comes with f where the weight needs it (one
    // pass over the shared terms), so only after the shadow ray is it read.
    const bool weighted = !ls->delta && strategy == LightStrategy::Mis;
    float bsdf_pdf = 0;
    const Spectrum f =
        bump_shadowed(sd, bsdf, wo, wi, ls->wi,
                      weighted ? bsdf_eval_pdf(bsdf, wo, wi, Transport::Radiance, &bsdf_pdf)
                               : bsdf_eval(bsdf, wo, wi, Transport::Radiance));
    if (is_black(f)) return Spectrum(0);
    const Ray shadow = spawn_ray_to(origins, ls->wi, ls->dist, ls->p, time);
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

// A light sample's draws: the light choice and the point on the light. Where the choice
// allows it, the point's first coordinate chooses the light too (rescaled, as Cycles
// does): the points on an emitter made of several triangles (the Cornell box's
// two-triangle panel) then stay stratified over all of it, not over each triangle apart;
// direct light's relMSE there falls 30% at 64 spp (docs/performance.md). The choice is
// drawn in every case, so that the sampler's dimensions do not depend on the light
// sampler (deferred: a remapping choice does not read it).
struct LightDraws {
    PathSampler::Deferred1d choice;
    Vec2 u;
};
inline LightDraws draw_light(PathSampler& sampler) {
    LightDraws d;
    d.choice = sampler.defer_1d();
    d.u = sampler.get_2d();
    return d;
}

// One light sample at the shading point from the draws `u` (draw_light), MIS-weighted
// against `bsdf_samples` BSDF samples per `light_samples` light samples when strategy is
// Mis. Returns f * Li * |cos| * w / pdf, times the transmittance of the medium the
// shadow ray starts in (media: wo's side for reflection, the far side for transmission;
// surfaces on the way block it). `origins` holds the shading point and the origins of
// the rays leaving it, which the vertex's continuation shares (RayOrigins). Inline into
// the path tracer's loop, its one caller: the call's set-up and its eleven arguments
// cost about 25 instructions a vertex, 1% of the render's (docs/performance.md,
// "Shapes of the hot path").
[[gnu::always_inline]] inline Spectrum sample_one_light(
    const RenderContext& ctx, const RayOrigins& origins, const ShadingData& sd, Vec3 wo, float time,
    const PathSampler& sampler, const LightDraws& u, LightStrategy strategy,
    float light_samples = 1, float bsdf_samples = 1, const SideMedia& media = {}) {
    const SurfacePoint& sp = origins.point();
    // The remapped coordinate goes to its own float: written through a pointer into u
    // and read back as the whole Vec2, it would make an 8-byte load wait for a 4-byte store.
    float u_x = u.u.x;
    const std::optional<SampledLight> chosen =
        ctx.lights.remaps_choice()
            ? ctx.lights.sample_remapped(u.u.x, &u_x)
            : ctx.lights.sample(ShadingPoint{sp.p, sd.ng}, sampler.value(u.choice));
    if (!chosen) return Spectrum(0);
    return sample_chosen_light(ctx, origins, sd, wo, time, &*chosen, Vec2(u_x, u.u.y), strategy,
                               light_samples, bsdf_samples, media);
}

// Distribution ray tracing's soft shadows: one light chosen for the point, then n shadow rays
// to n different points of it, stratified over the light (a Latin hypercube of its
// sample square). Returns the average of the n estimates, each MIS-weighted against
// `bsdf_samples` BSDF samples per n light samples.
Spectrum sample_light_stratified(const RenderContext& ctx, const SurfacePoint& sp,
                                 const ShadingData& sd, Vec3 wo, float time, Sampler& sampler,
                                 int n, LightStrategy strategy, float bsdf_samples = 1,
                                 const SideMedia& media = {});

// MIS weight for emission found by a BSDF-sampled ray that left `prev_p` with solid-angle
// density bsdf_pdf and hit `light` (a TriangleLight at hit_p, or the environment when
// hit_p is null) at the ray's time.
float emission_weight(const RenderContext& ctx, const Light* light, Vec3 prev_p, Vec3 prev_n,
                      const Vec3* hit_p, Vec3 wi, float time, float bsdf_pdf,
                      LightStrategy strategy, float light_samples = 1, float bsdf_samples = 1);
// The same where the caller has the light's density for the ray already (light_pdf,
// before the light set's choice of the light): the environment's Le(w, &pdf).
float emission_weight_for_pdf(const RenderContext& ctx, const Light* light, Vec3 prev_p,
                              Vec3 prev_n, float light_pdf, float bsdf_pdf,
                              LightStrategy strategy, float light_samples = 1,
                              float bsdf_samples = 1);

}  // namespace penumbra
