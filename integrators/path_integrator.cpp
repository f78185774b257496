#include "integrators/path_integrator.h"

#include <algorithm>
#include <cmath>

#include "core/sampling/path_sampler.h"
#include "core/camera/camera_culling.h"
#include "integrators/direct_lighting.h"
#include "materials/bsdf_calls.h"

namespace penumbra {

namespace {

// Cycles' clamp: the contribution scaled so its largest component is at most limit (0:
// off). Scaling, never raising, keeps the hue of what is clamped.
Spectrum clamped(Spectrum c, float limit) {
    if (limit <= 0) return c;
    const float m = max_component(c);
    return m > limit ? c * (limit / m) : c;
}

}  // namespace

Spectrum PathIntegrator::Li(const Ray& ray, const RenderContext& ctx, Sampler& sampler) const {
    return dispatch(ray, nullptr, ctx, sampler);
}

Spectrum PathIntegrator::Li_from_hit(const Ray& ray, const std::optional<Hit>& hit,
                                     const RenderContext& ctx, Sampler& sampler) const {
    return dispatch(ray, &hit, ctx, sampler);
}

Spectrum PathIntegrator::dispatch(const Ray& ray, const std::optional<Hit>* first_hit,
                                  const RenderContext& ctx, Sampler& sampler) const {
    if (ctx.has_volumes)
        return ctx.has_alpha ? trace<true, true>(ray, first_hit, ctx, sampler)
                             : trace<true, false>(ray, first_hit, ctx, sampler);
    return ctx.has_alpha ? trace<false, true>(ray, first_hit, ctx, sampler)
                         : trace<false, false>(ray, first_hit, ctx, sampler);
}

template <bool kMedia, bool kAlpha>
Spectrum PathIntegrator::trace(const Ray& camera_ray, const std::optional<Hit>* first_hit,
                               const RenderContext& ctx, Sampler& sampler) const {
    const LightStrategy strategy = m_options.strategy;
    Spectrum L(0), beta(1);
    // Product of (eta_i / eta_o)^2 over refractions: radiance scaling that Russian
    // roulette should not mistake for absorption (pbrt-v4's etaScale).
    float eta_scale = 1;
    Ray ray = camera_ray;
    // State of the previous vertex, for MIS on emitters that BSDF sampling finds.
    bool specular_bounce = false;
    float bsdf_pdf = 0;
    Vec3 prev_p, prev_n;
    int depth = 0;
    int passes = 0;  // surfaces skipped for alpha; bounded so a stack of holes ends
    PathMedia media;  // camera rays start outside all media
    // Light reaching the camera through at most one bounce is direct (for the clamps).
    auto clamp_for = [&](int bounces) {
        return bounces <= 1 ? m_options.clamp_direct : m_options.clamp_indirect;
    };
    MaterialOptions materials = ctx.materials;
    PathSampler draws(sampler);
    // A vertex's draws (its light sample, BSDF sample and roulette), taken before its ray
    // is traced where nothing else draws in between (no alpha, no media): the same values
    // as at their use, which a path that ends early does not reach, and no later draw
    // depends on them. Their hashes and table loads then run beside the ray's traversal,
    // not between the hit and the next ray: taken at their use they held 5.7% of the
    // point-light box's samples, twice their share of its instructions.
    constexpr bool kEarlyDraws = !kMedia && !kAlpha;
    struct VertexDraws {
        LightDraws light;
        Vec2 u_dir;
        // Deferred: the Lambertian model, the commonest, has one lobe and does not read it.
        PathSampler::Deferred1d lobe;
        float u_rr = 0;
    } early;
    // A culled surface is no vertex: the camera ray goes on with the draws already taken.
    bool keep_draws = false;
    for (;;) {
        if constexpr (kEarlyDraws) {
            if (!keep_draws) {
                early.light = draw_light(draws);
                early.u_dir = draws.get_2d();
                early.lobe = draws.defer_1d();
                if (depth + 1 >= m_options.rr_depth) early.u_rr = draws.get_1d();
            }
        }
        keep_draws = false;
        // The given hit is the camera ray's own: after a pass-through (alpha or culled),
        // trace again.
        const std::optional<Hit> hit =
            first_hit && depth == 0 && passes == 0 ? *first_hit : ctx.accel.intersect(ray);
        // The medium the segment lies in absorbs along it up to the hit. A ray that
        // escapes has left every closed volume, whatever the stack says: it can only
        // still hold one whose exit the ray grazed past within rounding at an edge. A
        // hit outside a volume's bounds likewise proves the path left it (leave_outside).
        if (kMedia && hit && !media.stack.empty()) {
            leave_outside(ctx, media.stack, ray.o + ray.d * hit->t);
            beta *= segment_transmittance(ctx, media.stack, ray, hit->t);
            if (is_black(beta)) break;
        }
        // Emission that a camera ray or a specular bounce finds can only come from BSDF
        // sampling: no light sample could have produced it.
        const bool unweighted = depth == 0 || specular_bounce;
        if (!hit) {
            if (const EnvironmentLight* env = ctx.lights.environment()) {
                const Vec3 wi = normalize(ray.d);
                float w = 1, env_pdf;
                // Weighted, Le and the density come from one mapping of wi to the image.
                const Spectrum Le = unweighted ? env->Le(wi) : env->Le(wi, &env_pdf);
                if (!unweighted)
                    w = emission_weight_for_pdf(ctx, env, prev_p, prev_n, env_pdf, bsdf_pdf,
                                                strategy);
                L += clamped(beta * Le * w, clamp_for(depth));
            }
            break;
        }
        const SurfacePoint sp = make_surface_point(ctx.scene, ray, *hit);
        // Only the camera's straight line culls back faces (camera_culling.h); after a
        // bounce the path carries light, which sees both sides.
        if (depth == 0 && ctx.camera_culling && camera_culls(ctx.scene, sp, ray.d)) {
            pass_culled(sp, ray);
            if (++passes > 256) break;
            keep_draws = true;
            continue;
        }
        const Vec3 wo_world = normalize(-ray.d);
        // Without volumes these change nothing and draw no sample (path_media.h).
        PathVolume volume;
        if (kMedia) {
            dispersion_channel(ctx, media, sp.material, sampler, beta);
            const bool front = dot(wo_world, sp.ng) >= 0;  // as shade() decides it
            volume = path_volume(ctx, media, sp.material, front);
        }
        const ShadingData sd = shade(ctx.scene, sp, wo_world, materials, volume);

        // Without MASK or BLEND materials every coverage is 1 and nothing passes.
        Coverage cover;
        if (kAlpha) {
            cover = partial_coverage(sd, sampler);
            if (cover.through && !(cover.share > 0)) {  // a hole: nothing to shade
                step_through(sp, sd, ray);
                if (++passes > 256) break;  // a stack of holes ends the path
                continue;
            }
        }

        if (!is_black(sd.emission)) {
            float w = 1;
            if (!unweighted) {
                const Light* light = ctx.lights.triangle_light(hit->instance, hit->mesh, hit->prim);
                w = emission_weight(ctx, light, prev_p, prev_n, &sp.p, wo_world * -1.0f,
                                    ray.time, bsdf_pdf, strategy);
            }
            L += clamped(beta * sd.emission * (w * cover.share), clamp_for(depth));
        }
        if (depth >= m_options.max_depth && !cover.through) break;

        const Bsdf& bsdf = *sd.bsdf.get();
        const Vec3 wo = to_bsdf_local(bsdf, sd.frame, wo_world);
        // The light sample's shadow ray and the continuation share their origin when
        // they leave on the same side.
        const RayOrigins origins(sp);
        const SideMedia sides =
            kMedia ? side_media(ctx, media.stack, sp.material, sd.front_face) : SideMedia{};
        // The next vertex (depth max_depth) takes no light sample: the BSDF sample's ray
        // there could only find emission. Where nothing a ray can reach emits, the path
        // ends here with the same radiance, one ray and one shading short (as Embree's
        // pathtracer tutorial does after its last segment).
        const bool last =
            depth + 1 >= m_options.max_depth && !ctx.has_emission && !ctx.lights.environment();
        auto sample_bsdf = [&](Vec2 u_dir, float u_lobe) {
            return bsdf_sample(bsdf, wo, u_lobe, u_dir, Transport::Radiance);
        };
        // With the draws taken early, the BSDF sample, which needs nothing of the light
        // sample, is taken before it: its chain (the disk mapping's division and square
        // root, the frame) then runs beside the light sample's, where after the shadow
        // ray's traversal it stood between that and the next ray. The same values.
        const std::optional<BsdfSample> early_bs =
            kEarlyDraws && !last
                ? sample_bsdf(early.u_dir, bsdf.is_lambertian() ? 0.0f : draws.value(early.lobe))
                : std::nullopt;
        if (depth < m_options.max_depth)
            L += clamped(beta * cover.share *
                             sample_one_light(ctx, origins, sd, wo, ray.time, draws,
                                              kEarlyDraws ? early.light : draw_light(draws),
                                              strategy, 1, 1, sides),
                         clamp_for(depth + 1));
        if (cover.through) {
            step_through(sp, sd, ray);
            if (++passes > 256) break;
            continue;
        }
        if (last) break;

        const std::optional<BsdfSample> late_bs = kEarlyDraws ? std::nullopt : [&] {
            // The square first, then the lobe choice: the order GCC gave the two calls as
            // arguments (unspecified in C++), written out so every compiler draws the same.
            const Vec2 u_dir = draws.get_2d();
            const float u_lobe = draws.get_1d();
            return sample_bsdf(u_dir, u_lobe);
        }();
        const std::optional<BsdfSample>& bs = kEarlyDraws ? early_bs : late_bs;
        if (!bs) break;
        const Vec3 wi_world = sd.frame.to_world(bs->wi);
        // Directions the interpolated normal puts on the other side than the lobe would
        // cross the surface (or leak): end the path there. The same test as the light
        // samples', so that MIS weighs two strategies that cover the same directions.
        if ((bs->wi.z > 0) != (dot(wi_world, sd.n_side) > 0)) break;
        // The same bump shadowing as the light samples' (direct_lighting.h); specular
        // lobes have no diffuse part.
        beta *= sd.bumped && !bs->is_specular()
                    ? bump_shadowed(sd, bsdf, wo, bs->wi, wi_world, bs->f) *
                          (std::abs(bs->wi.z) / bs->pdf)
                    : bs->weight();
        // The frame faces wo: a sample below it crossed the surface, into or out of a volume.
        if (kMedia && bs->wi.z < 0)
            cross_surface(ctx, media.stack, sp.material, sd.front_face, int(sp.instance));
        eta_scale *= bs->eta * bs->eta;
        specular_bounce = bs->is_specular();
        if (!specular_bounce && m_options.regularize_roughness > 0)
            materials.min_roughness = m_options.regularize_roughness;
        bsdf_pdf = bs->pdf;
        prev_p = sp.p;
        prev_n = sd.ng;
        ++depth;
        if (!is_finite(beta) || is_black(beta)) break;

        if (depth >= m_options.rr_depth) {
            // Continue with probability sqrt(throughput), capped at 1, as Cycles'
            // path_state_continuation_probability: milder than pbrt-v4's linear rule, whose
            // survivors (throughput then 1) face a cut at every further bounce; 9-10% better
            // relMSE x time on the Lambertian Cornell box (docs/performance.md).
            const float p = std::min(1.0f, std::sqrt(max_component(beta) * eta_scale));
            if ((kEarlyDraws ? early.u_rr : draws.get_1d()) < 1 - p) break;
            beta /= p;
        }
        ray.cone = bounce_cone(ray.cone, sp.cone_width, bs->pdf, bs->is_specular());
        continue_ray(ray, origins, wi_world);
    }
    return L;
}

}  // namespace penumbra
