// What a camera ray sees first: the first surface it does not pass through (shared by
// the first-hit AOVs and the denoiser's guides), and the first-hit AOVs (albedo, shading
// normal, distance, position, IDs, motion vector), computed only when asked for. They
// take the path integrator's first vertex where it is that surface (FirstVertex);
// otherwise, and for other integrators, they find and shade it with their own ray casts.
#pragma once

#include <cstdint>
#include <optional>

#include "core/film/aov.h"
#include "core/film/cryptomatte.h"
#include "core/sampling/rng.h"
#include "core/surface_point.h"
#include "integrators/integrator.h"
#include "materials/material.h"

namespace penumbra {

struct VisibleSurface {
    SurfacePoint sp;
    ShadingData sd;  // shaded for wo = -ray.d
    Hit hit;         // the accelerator's hit that sp was made from
};

// Traces `ray` to the first surface it does not pass through; empty if it escapes.
// Alpha-masked and blended surfaces are passed through stochastically, as the
// integrators do, with numbers from rng; `ray` is left as the segment that hit. With
// `camera` (a camera ray before its first bounce; false for a bounced ray), the backs of
// single-sided surfaces are passed through too (camera_culling.h). first_hit: the ray's
// closest hit where it was traced already (a camera packet's), else nullptr.
std::optional<VisibleSurface> first_visible_surface(Ray& ray, const RenderContext& ctx, Rng& rng,
                                                    bool camera = true,
                                                    const std::optional<Hit>* first_hit = nullptr);

// The first-hit AOVs of ray (a camera ray). The random numbers are hashed from `key`
// (seed, pixel, sample) rather than drawn from the sampler, so the beauty's sample
// streams are the same with and without AOVs.
// first_hit: as first_visible_surface's. known: the integrator's first vertex (taken
// where valid, without tracing or shading again). hashes: where given, the Cryptomatte
// hashes are filled in (the film reads them only for its Cryptomatte layers).
AovRecord first_hit_aovs(const Ray& ray, const RenderContext& ctx, uint64_t key,
                         const std::optional<Hit>* first_hit = nullptr,
                         const FirstVertex* known = nullptr,
                         const CryptomatteHashes* hashes = nullptr);

}  // namespace penumbra
