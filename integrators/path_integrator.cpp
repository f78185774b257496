#include "integrators/path_integrator.h"

#include <algorithm>
#include <cmath>

#include "core/camera/camera_culling.h"
#include "core/sampling/path_sampler.h"
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

// Light reaching the camera through at most one bounce is direct (for the clamps).
[[gnu::always_inline]] inline float clamp_for(const IntegratorOptions& o, int bounces) {
    return bounces <= 1 ? o.clamp_direct : o.clamp_indirect;
}

// What the path carries from vertex to vertex. Plain scalars, none of whose addresses
// leaves the inlined stages, so that the compiler keeps them in registers as it keeps
// separate locals.
struct PathState {
    Spectrum L{0}, beta{1};
    // Product of (eta_i / eta_o)^2 over refractions: radiance scaling that Russian
    // roulette should not mistake for absorption (pbrt-v4's etaScale).
    float eta_scale = 1;
    // The previous vertex, for MIS on emitters that BSDF sampling finds.
    bool specular_bounce = false;
    float bsdf_pdf = 0;
    Vec3 prev_p, prev_n;
    int depth = 0;
    int passes = 0;  // surfaces skipped for alpha; bounded so a stack of holes ends
};

// A vertex's draws (its light sample, BSDF sample and roulette), taken before its ray
// is traced where nothing else draws in between (no alpha, no media): the same values
// as at their use, which a path that ends early does not reach, and no later draw
// depends on them. Their hashes and table loads then run beside the ray's traversal,
// not between the hit and the next ray, where they would stall the vertex.
struct VertexDraws {
    LightDraws light;
    Vec2 u_dir;
    // Deferred: the Lambertian model, the commonest, has one lobe and does not read it.
    PathSampler::Deferred1d lobe;
    float u_rr = 0;
};

[[gnu::always_inline]] inline void take_vertex_draws(PathSampler& draws, const IntegratorOptions& o,
                                                     int depth, VertexDraws& early) {
    early.light = draw_light(draws);
    early.u_dir = draws.get_2d();
    early.lobe = draws.defer_1d();
    if (depth + 1 >= o.rr_depth) early.u_rr = draws.get_1d();
}

// The environment's light that an escaped ray finds, MIS-weighted unless only BSDF
// sampling could have found it.
[[gnu::always_inline]] inline void add_escaped_light(const RenderContext& ctx,
                                                     const IntegratorOptions& o, const Ray& ray,
                                                     bool unweighted, PathState& path) {
    const EnvironmentLight* env = ctx.lights.environment();
    if (!env) return;
    const Vec3 wi = normalize(ray.d);
    float w = 1, env_pdf;
    // Weighted, Le and the density come from one mapping of wi to the image.
    const Spectrum Le = unweighted ? env->Le(wi) : env->Le(wi, &env_pdf);
    if (!unweighted)
        w = emission_weight_for_pdf(ctx, env, path.prev_p, path.prev_n, env_pdf, path.bsdf_pdf,
                                    o.strategy);
    path.L += clamped(path.beta * Le * w, clamp_for(o, path.depth));
}

// The medium the segment lies in absorbs along it up to the hit at t; true where nothing
// is left. A ray that escapes has left every closed volume, whatever the stack says: it
// can only still hold one whose exit the ray grazed past within rounding at an edge. A
// hit outside a volume's bounds likewise proves the path left it (leave_outside).
[[gnu::always_inline]] inline bool absorbed(const RenderContext& ctx, const Ray& ray, float t,
                                            PathMedia& media, PathState& path) {
    leave_outside(ctx, media.stack, ray.o + ray.d * t);
    path.beta *= segment_transmittance(ctx, media.stack, ray, t);
    return is_black(path.beta);
}

// The hit's shading, after the path's volumes have fixed its colour channel and the IOR
// on the far side. Without volumes these change nothing and draw no sample
// (path_media.h).
template <bool kMedia>
[[gnu::always_inline]] inline ShadingData shade_vertex(const RenderContext& ctx,
                                                       const SurfacePoint& sp, Vec3 wo_world,
                                                       const MaterialOptions& materials,
                                                       PathMedia& media, Sampler& sampler,
                                                       PathState& path) {
    PathVolume volume;
    if (kMedia) {
        // Through a copy: the state's address stays inside the inlined stages.
        Spectrum beta = path.beta;
        dispersion_channel(ctx, media, sp.material, sampler, beta);
        path.beta = beta;
        const bool front = dot(wo_world, sp.ng) >= 0;  // as shade() decides it
        volume = path_volume(ctx, media, sp.material, front);
    }
    return shade(ctx.scene, sp, wo_world, materials, volume);
}

// Emission at the hit, MIS-weighted against the light sample that could have found it
// unless only BSDF sampling could have (unweighted), and scaled by the surface's coverage.
[[gnu::always_inline]] inline void add_hit_emission(const RenderContext& ctx,
                                                    const IntegratorOptions& o, const Hit& hit,
                                                    const SurfacePoint& sp, const ShadingData& sd,
                                                    const Ray& ray, Vec3 wo_world, bool unweighted,
                                                    float share, PathState& path) {
    if (is_black(sd.emission)) return;
    float w = 1;
    if (!unweighted) {
        const Light* light = ctx.lights.triangle_light(hit.instance, hit.mesh, hit.prim);
        w = emission_weight(ctx, light, path.prev_p, path.prev_n, &sp.p, wo_world * -1.0f, ray.time,
                            path.bsdf_pdf, o.strategy);
    }
    path.L += clamped(path.beta * sd.emission * (w * share), clamp_for(o, path.depth));
}

// Next-event estimation: one light sample from the draws u, MIS-weighted against the
// BSDF's, scaled by the surface's coverage (share).
[[gnu::always_inline]] inline void add_light_sample(
    const RenderContext& ctx, const IntegratorOptions& o, const RayOrigins& origins,
    const ShadingData& sd, Vec3 wo, float time, const PathSampler& draws, const LightDraws& u,
    const SideMedia& sides, float share, PathState& path) {
    path.L +=
        clamped(path.beta * share *
                    sample_one_light(ctx, origins, sd, wo, time, draws, u, o.strategy, 1, 1, sides),
                clamp_for(o, path.depth + 1));
}

// The next vertex (depth max_depth) takes no light sample: the BSDF sample's ray there
// could only find emission. Where nothing a ray can reach emits, the path ends at this
// one (the last) with the same radiance, one ray and one shading short (as Embree's
// pathtracer tutorial does after its last segment).
[[gnu::always_inline]] inline bool last_vertex(const RenderContext& ctx, const IntegratorOptions& o,
                                               int depth) {
    return depth + 1 >= o.max_depth && !ctx.has_emission && !ctx.lights.environment();
}

// With the draws taken early, the BSDF sample, which needs nothing of the light sample,
// is taken before it: its chain (the disk mapping's division and square root, the
// frame) then runs beside the light sample's, where after the shadow ray's traversal it
// would stand between that and the next ray. The same values.
[[gnu::always_inline]] inline std::optional<BsdfSample> sample_bsdf_early(
    const Bsdf& bsdf, Vec3 wo, const PathSampler& draws, const VertexDraws& early) {
    return bsdf_sample(bsdf, wo, bsdf.is_lambertian() ? 0.0f : draws.value(early.lobe), early.u_dir,
                       Transport::Radiance);
}

// The BSDF sample from draws taken at its use. The square first, then the lobe choice:
// the order GCC gave the two calls as arguments (unspecified in C++), written out so
// every compiler draws the same.
[[gnu::always_inline]] inline std::optional<BsdfSample> sample_bsdf_now(const Bsdf& bsdf, Vec3 wo,
                                                                        PathSampler& draws) {
    const Vec2 u_dir = draws.get_2d();
    const float u_lobe = draws.get_1d();
    return bsdf_sample(bsdf, wo, u_lobe, u_dir, Transport::Radiance);
}

// Directions the interpolated normal puts on the other side than the lobe would cross
// the surface (or leak): the path ends there. The same test as the light samples', so
// that MIS weighs two strategies that cover the same directions.
[[gnu::always_inline]] inline bool leaks(const BsdfSample& bs, Vec3 wi_world,
                                         const ShadingData& sd) {
    return (bs.wi.z > 0) != (dot(wi_world, sd.n_side) > 0);
}

// Follows the BSDF sample bs (wi_world: its direction in the world) to the next vertex:
// the throughput with the same bump shadowing as the light samples' (direct_lighting.h;
// specular lobes have no diffuse part), the volume the sample enters or leaves, and what
// MIS at the next vertex needs of this one.
template <bool kMedia>
[[gnu::always_inline]] inline void follow_bsdf_sample(
    const RenderContext& ctx, const IntegratorOptions& o, const SurfacePoint& sp,
    const ShadingData& sd, const Bsdf& bsdf, Vec3 wo, const BsdfSample& bs, Vec3 wi_world,
    PathMedia& media, MaterialOptions& materials, PathState& path) {
    path.beta *=
        sd.bumped && !bs.is_specular()
            ? bump_shadowed(sd, bsdf, wo, bs.wi, wi_world, bs.f) * (std::abs(bs.wi.z) / bs.pdf)
            : bs.weight();
    // The frame faces wo: a sample below it crossed the surface, into or out of a volume.
    if (kMedia && bs.wi.z < 0)
        cross_surface(ctx, media.stack, sp.material, sd.front_face, int(sp.instance));
    path.eta_scale *= bs.eta * bs.eta;
    path.specular_bounce = bs.is_specular();
    if (!path.specular_bounce && o.regularize_roughness > 0)
        materials.min_roughness = o.regularize_roughness;
    path.bsdf_pdf = bs.pdf;
    path.prev_p = sp.p;
    path.prev_n = sd.ng;
    ++path.depth;
}

// Russian roulette: continue with probability sqrt(throughput), capped at 1, as Cycles'
// path_state_continuation_probability: milder than pbrt-v4's linear rule, whose
// survivors (throughput then 1) face a cut at every further bounce; 9-10% better
// relMSE x time on the Lambertian Cornell box (docs/performance.md).
[[gnu::always_inline]] inline bool survives_roulette(float u, PathState& path) {
    const float p = std::min(1.0f, std::sqrt(max_component(path.beta) * path.eta_scale));
    if (u < 1 - p) return false;
    path.beta /= p;
    return true;
}

// What the first-hit AOVs read of the first vertex (FirstVertex).
inline void record_first_vertex(const Hit& hit, const SurfacePoint& sp, const ShadingData& sd,
                                FirstVertex& first) {
    first.valid = true;
    first.hit = hit;
    first.p = sp.p;
    first.instance = sp.instance;
    first.material = sp.material;
    first.albedo = sd.base_color;
    first.normal = sd.frame.n;
}

}  // namespace

Spectrum PathIntegrator::Li(const Ray& ray, const RenderContext& ctx, Sampler& sampler) const {
    return dispatch(ray, nullptr, ctx, sampler, nullptr);
}

Spectrum PathIntegrator::Li_from_hit(const Ray& ray, const std::optional<Hit>& hit,
                                     const RenderContext& ctx, Sampler& sampler,
                                     FirstVertex* first) const {
    return dispatch(ray, &hit, ctx, sampler, first);
}

Spectrum PathIntegrator::dispatch(const Ray& ray, const std::optional<Hit>* first_hit,
                                  const RenderContext& ctx, Sampler& sampler,
                                  FirstVertex* first) const {
    if (ctx.has_volumes)
        return ctx.has_alpha ? trace<true, true>(ray, first_hit, ctx, sampler, first)
                             : trace<true, false>(ray, first_hit, ctx, sampler, first);
    return ctx.has_alpha ? trace<false, true>(ray, first_hit, ctx, sampler, first)
                         : trace<false, false>(ray, first_hit, ctx, sampler, first);
}

template <bool kMedia, bool kAlpha>
Spectrum PathIntegrator::trace(const Ray& camera_ray, const std::optional<Hit>* first_hit,
                               const RenderContext& ctx, Sampler& sampler,
                               FirstVertex* first) const {
    const IntegratorOptions& o = m_options;
    PathState path;
    Ray ray = camera_ray;
    PathMedia media;  // camera rays start outside all media
    MaterialOptions materials = ctx.materials;
    PathSampler draws(sampler);
    // The vertex's draws taken before its ray where nothing else draws in between.
    constexpr bool kEarlyDraws = !kMedia && !kAlpha;
    VertexDraws early;
    // A culled surface is no vertex: the camera ray goes on with the draws already taken.
    bool keep_draws = false;
    // The camera ray passed a surface by a coin flip (alpha): the first-hit AOVs flip
    // their own coins, so this path's first vertex need not be their surface.
    bool flipped = false;
    for (;;) {
        if (kEarlyDraws && !keep_draws) take_vertex_draws(draws, o, path.depth, early);
        keep_draws = false;
        // The given hit is the camera ray's own: after a pass-through (alpha or culled),
        // trace again.
        const std::optional<Hit> hit = first_hit && path.depth == 0 && path.passes == 0
                                           ? *first_hit
                                           : ctx.accel.intersect(ray);
        if (kMedia && hit && !media.stack.empty() && absorbed(ctx, ray, hit->t, media, path)) break;
        // Emission that a camera ray or a specular bounce finds can only come from BSDF
        // sampling: no light sample could have produced it.
        const bool unweighted = path.depth == 0 || path.specular_bounce;
        if (!hit) {
            // A transparent background hides the environment from camera rays only.
            if (path.depth > 0 || !o.transparent_background)
                add_escaped_light(ctx, o, ray, unweighted, path);
            break;
        }
        const SurfacePoint sp = make_surface_point(ctx.scene, ray, *hit);
        // Only the camera's straight line culls back faces (camera_culling.h); after a
        // bounce the path carries light, which sees both sides.
        if (path.depth == 0 && ctx.camera_culling && camera_culls(ctx.scene, sp, ray.d)) {
            pass_culled(sp, ray);
            if (++path.passes > 256) break;
            keep_draws = true;
            continue;
        }
        const Vec3 wo_world = normalize(-ray.d);
        const ShadingData sd =
            shade_vertex<kMedia>(ctx, sp, wo_world, materials, media, sampler, path);

        if (first && path.depth == 0 && !flipped && sd.opacity >= 1)
            record_first_vertex(*hit, sp, sd, *first);

        // Without MASK or BLEND materials every coverage is 1 and nothing passes.
        Coverage cover;
        if (kAlpha) {
            cover = partial_coverage(sd, sampler);
            flipped |= path.depth == 0 && sd.opacity > 0 && sd.opacity < 1;
            if (cover.through && !(cover.share > 0)) {  // a hole: nothing to shade
                step_through(sp, sd, ray);
                if (++path.passes > 256) break;  // a stack of holes ends the path
                continue;
            }
        }
        add_hit_emission(ctx, o, *hit, sp, sd, ray, wo_world, unweighted, cover.share, path);
        if (path.depth >= o.max_depth && !cover.through) break;

        const Bsdf& bsdf = *sd.bsdf.get();
        const Vec3 wo = to_bsdf_local(bsdf, sd.frame, wo_world);
        // The light sample's shadow ray and the continuation share their origin when
        // they leave on the same side.
        const RayOrigins origins(sp);
        const SideMedia sides =
            kMedia ? side_media(ctx, media.stack, sp.material, sd.front_face) : SideMedia{};
        const bool last = last_vertex(ctx, o, path.depth);
        const std::optional<BsdfSample> early_bs =
            kEarlyDraws && !last ? sample_bsdf_early(bsdf, wo, draws, early) : std::nullopt;
        if (path.depth < o.max_depth)
            add_light_sample(ctx, o, origins, sd, wo, ray.time, draws,
                             kEarlyDraws ? early.light : draw_light(draws), sides, cover.share,
                             path);
        if (cover.through) {
            step_through(sp, sd, ray);
            if (++path.passes > 256) break;
            continue;
        }
        if (last) break;

        const std::optional<BsdfSample> late_bs =
            kEarlyDraws ? std::nullopt : sample_bsdf_now(bsdf, wo, draws);
        const std::optional<BsdfSample>& bs = kEarlyDraws ? early_bs : late_bs;
        if (!bs) break;
        const Vec3 wi_world = sd.frame.to_world(bs->wi);
        if (leaks(*bs, wi_world, sd)) break;
        follow_bsdf_sample<kMedia>(ctx, o, sp, sd, bsdf, wo, *bs, wi_world, media, materials, path);
        if (!is_finite(path.beta) || is_black(path.beta)) break;
        if (path.depth >= o.rr_depth &&
            !survives_roulette(kEarlyDraws ? early.u_rr : draws.get_1d(), path))
            break;
        ray.cone = bounce_cone(ray.cone, sp.cone_width, bs->pdf, bs->is_specular());
        continue_ray(ray, origins, wi_world);
    }
    return path.L;
}

}  // namespace penumbra
