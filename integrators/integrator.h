// Integrators estimate the radiance arriving along a camera ray. They see the scene
// only through the Accel interface and the plain Scene data.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/accel/accel.h"
#include "core/lights/light_set.h"
#include "core/media/medium_set.h"
#include "core/sampling/sampler.h"
#include "core/scene/scene.h"
#include "materials/bsdf_prototypes.h"
#include "materials/material.h"

namespace penumbra {

struct MotionVectorCameras;  // integrators/motion_vector.h

// What an integrator traces against: the scene data, its accelerator and its lights.
// The scene's media are built here, from its materials, so that every render (CLI,
// tests, benchmarks) sees the same volumes.
// The materials' BSDF prototypes are built here too, from the materials as they are
// then (a context is made per render; the scene's materials must not change under it),
// and materials points to them.
struct RenderContext {
    RenderContext(const Scene& scene, const Accel& accel, const LightSet& lights,
                  bool has_alpha = false, const MaterialOptions& materials = {})
        : scene(scene),
          accel(accel),
          lights(lights),
          has_alpha(has_alpha),
          materials(materials),
          ray_cones(!scene.textures.empty()),
          media(scene),
          has_volumes(media.any()),
          has_emission(scene_has_emission(scene)),
          prototypes(std::make_shared<const BsdfPrototypes>(scene, materials)) {
        this->materials.prototypes = prototypes.get();
    }

    const Scene& scene;
    const Accel& accel;
    const LightSet& lights;
    bool has_alpha = false;  // some material is MASK or BLEND: rays test coverage
    // Camera rays pass through the backs of single-sided surfaces (camera_culling.h), as
    // in every render. Off, Li is the radiance along any ray, wherever it starts: for
    // measuring light transport from inside a scene.
    bool camera_culling = true;
    // How glTF materials become BSDFs (--microfacet). A caller that changes the
    // distribution or layering afterwards gets no prototypes (BsdfPrototypes::find).
    MaterialOptions materials{};
    // Ray cones only choose texture levels: without textures camera rays carry none, and
    // no hit or bounce pays for a footprint (two square roots and a division a vertex).
    bool ray_cones = true;
    MediumSet media;  // the interior of each material with a volume
    // Some material has a volume (and so possibly dispersion): without one, the path
    // tracer skips its media bookkeeping for the whole render.
    bool has_volumes = false;
    // Some material emits (scene_has_emission). Without it and without an environment,
    // only light samples find light (punctual lights cannot be hit), and the path tracer
    // ends a path at its last light sample instead of tracing a ray that finds nothing.
    bool has_emission = true;
    // Shared by copies, so that each copy's materials.prototypes stays valid.
    std::shared_ptr<const BsdfPrototypes> prototypes;
    // The cameras motion vectors map points with (Aov::Vector); nullptr: no vectors.
    const MotionVectorCameras* motion_vectors = nullptr;
};

// Which strategies estimate light from non-delta emitters in "path": both with MIS, or
// only one (to measure what MIS buys). Delta lights are always sampled.
enum class LightStrategy { Mis, BsdfOnly, LightOnly };

struct IntegratorOptions {
    int max_depth = 8;  // path: bounces; basic/direct: specular recursion
    int rr_depth = 3;   // path: Russian roulette from this depth on
    LightStrategy strategy = LightStrategy::Mis;
    int light_samples = 1;  // direct: shadow rays per shading point
    int bsdf_samples = 1;   // direct: BSDF samples per shading point
    // path, firefly control (off at 0; biased when on). Each contribution's largest
    // component is clamped to these, as Cycles' sample_clamp_direct / _indirect: direct
    // light has at most one bounce between camera and emitter, indirect more.
    float clamp_direct = 0, clamp_indirect = 0;
    // path: path regularization (Cycles' "filter glossy", a roughening in the spirit of
    // Kaplanyan & Dachsbacher 2013): after the first non-specular bounce, glTF materials
    // are shaded with at least this roughness, so near-specular lobes met later (the
    // caustic paths diffuse -> mirror -> light) become glossy and NEE can find the light.
    float regularize_roughness = 0;
    // path, direct, basic: a transparent background. Camera rays that escape (past any
    // surfaces they pass through) find no environment, so the colour there is 0 and the
    // render loop's alpha (Aov::Coverage) says where geometry is; the environment still
    // lights the scene and is seen in reflections and through refraction.
    bool transparent_background = false;
};

// A camera ray's first visible surface as an integrator's first path vertex shaded it:
// what the first-hit AOVs read (first_hit.h), which otherwise find and shade that surface
// a second time, and a full coverage for a transparent background (camera_coverage.h).
// Filled only where it is the surface first_visible_surface returns: no stochastic alpha
// pass-through before it, and fully opaque.
struct FirstVertex {
    bool valid = false;
    Vec3 p;
    uint32_t instance = 0;
    int material = -1;
    Spectrum albedo;  // ShadingData::base_color
    Vec3 normal;      // the shading normal
    Hit hit;          // the accelerator's hit (motion vectors read its triangle and barycentrics)
};

class Integrator {
public:
    virtual ~Integrator() = default;
    // Radiance along ray (world space). Uses sampler dimensions after the camera's.
    virtual Spectrum Li(const Ray& ray, const RenderContext& ctx, Sampler& sampler) const = 0;
    // The same for a camera ray whose closest hit the caller has traced already (empty: a
    // miss), as the render loop does for packets of camera rays; the result must equal
    // Li(ray, ...) for that hit. The default ignores the hit and traces again.
    // first: where given, filled with the first vertex where the integrator records it
    // (FirstVertex); left invalid otherwise.
    virtual Spectrum Li_from_hit(const Ray& ray, const std::optional<Hit>& hit,
                                 const RenderContext& ctx, Sampler& sampler,
                                 FirstVertex* first = nullptr) const {
        (void)hit;
        (void)first;
        return Li(ray, ctx, sampler);
    }
    // Whether Li_from_hit uses the hit (only then does the loop trace camera packets).
    virtual bool uses_first_hit() const { return false; }
    // Whether every light sample it takes of a non-delta light is MIS-weighted against a
    // BSDF sample that can reach the same directions: then the environment may leave
    // its dimmer directions to the BSDF samples (EnvironmentSampling::MisCompensated).
    virtual bool pairs_light_and_bsdf_samples() const { return false; }
};

// Path, direct and basic estimate radiance; the others are debug views of the first hit.
enum class IntegratorType {
    Path,
    Direct,
    Basic,
    ShadingNormal,
    GeometricNormal,
    Albedo,
    Depth,
    Uv,
    Instance
};

std::unique_ptr<Integrator> make_integrator(IntegratorType type, const IntegratorOptions& options);

}  // namespace penumbra
