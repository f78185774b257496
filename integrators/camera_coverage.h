// A camera ray's coverage of geometry: the alpha of a transparent background. It is 1
// minus the share of the ray that passes every surface on its straight line and escapes,
// walking the line as the integrators' camera rays do (backs of single-sided surfaces
// culled, alpha holes passed) but taking each partly covered surface's transparency as a
// product, without the integrators' coin flips, so that a blended surface over nothing
// has its exact opacity in every sample.
#pragma once

#include <optional>

#include "core/accel/accel.h"
#include "core/ray.h"
#include "integrators/integrator.h"

namespace penumbra {

// The coverage of camera_ray in [0, 1]; first_hit: its closest hit when traced already
// (nullptr: trace it). Without alpha materials it is 1 at the first surface the camera
// does not cull and 0 where there is none. A transmissive surface (glass) covers: what is
// seen through it is light its refraction found, not the background (Cycles' Film >
// Transparent without "Transparent Glass").
float camera_coverage(const Ray& camera_ray, const RenderContext& ctx,
                      const std::optional<Hit>* first_hit);

}  // namespace penumbra
