// Next-event estimation and multiple importance sampling shared by the path and direct
// integrators (like Tungsten's TraceBase): light sampling, shadow rays through
// alpha-blended surfaces, and the power heuristic.
#pragma once

#include <algorithm>

#include "core/sampling/path_sampler.h"
#include "core/surface_point.h"
#include "integrators/integrator.h"
#include "integrators/path_media.h"
#include "materials/material.h"

namespace penumbra {

// Veach's power heuristic (beta = 2) for nf samples of density f_pdf against ng of g_pdf.
inline float power_heuristic(float nf, float f_pdf, float ng, float g_pdf) {
    const float f = nf * f_pdf, g = ng * g_pdf;
    if (std::isinf(f * f)) return 1;
    const float denom = f * f + g * g;
    return denom > 0 ? (f * f) / denom : 0.0f;
}

// The bump terminator fix (Conty Estevez et al. 2019, "A Microfacet-Based Shadowing
// Function to Solve the Bump Terminator Problem", Ray Tracing Gems ch. 12): light at wi
// on a normal-mapped surface is scaled by G = min(1, <n_s, wi> / (<n_b, wi> <n_s, n_b>)),
// smoothed to -G^3 + G^2 + G, with n_s the unperturbed (interpolated) normal and n_b the
// mapped one, both on the viewer's side. Without a normal map n_b = n_s and this is
// exactly 1. Transmitted light (wi below n_b) is left alone.
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
    // By reference: a copy of the ray spawn_ray just wrote stalls on store forwarding.
    if (!ctx.has_alpha) return ctx.accel.occluded(shadow) ? 0.0f : 1.0f;
    return shadow_transmittance_through(ctx, shadow);
}

// One light sample at the shading point, MIS-weighted against `bsdf_samples` BSDF samples
// per `light_samples` light samples when strategy is Mis. Returns f * Li * |cos| * w / pdf,
// times the transmittance of the medium the shadow ray starts in (media: wo's side for
// reflection, the far side for transmission; surfaces on the way block it).
Spectrum sample_one_light(const RenderContext& ctx, const SurfacePoint& sp,
                          const ShadingData& sd, Vec3 wo, float time, PathSampler& sampler,
                          LightStrategy strategy, float light_samples = 1,
                          float bsdf_samples = 1, const SideMedia& media = {});

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
