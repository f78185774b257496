// The first-hit AOVs of a camera sample: what the camera ray sees first (albedo,
// shading normal, distance, position), found with its own ray cast only when AOVs are
// asked for, so integrators stay unaware of them.
#pragma once

#include <cstdint>

#include "core/film/aov.h"
#include "integrators/integrator.h"

namespace penumbra {

// Traces ray (a camera ray) to its first visible surface. Alpha-masked and blended
// surfaces are passed through stochastically, as the integrators do, with a random
// number hashed from `key` (seed, pixel, sample) rather than drawn from the sampler, so
// the beauty's sample streams are the same with and without AOVs.
AovRecord first_hit_aovs(const Ray& ray, const RenderContext& ctx, uint64_t key);

}  // namespace penumbra
