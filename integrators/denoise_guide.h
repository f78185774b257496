// The denoiser's guide features of a camera sample: the first non-specular surface the
// camera ray reaches through mirrors and smooth glass, as Cycles' and OIDN's guides do,
// so that what a mirror or a pane of glass shows gets guides of its own.
#pragma once

#include <cstdint>

#include "core/film/aov.h"
#include "integrators/integrator.h"

namespace penumbra {

// Specular bounces a guide follows; at the last it takes the surface it is at.
inline constexpr int kMaxGuideBounces = 8;

// Follows ray (a camera ray) through alpha pass-throughs (as first_hit_aovs) and delta
// reflections and refractions, the lobe chosen by sampling the BSDF, to the first surface
// whose sampled lobe is not specular. There: albedo = the specular samples' weights
// (f |cos| / pdf, in importance transport, so refraction's radiance scaling stays out) x
// the base colour; normal = the world shading normal facing the incoming ray; depth =
// the path's length from the camera; visibility = whether one light sample from there is
// unoccluded (its transmittance). Random numbers are hashed from `key` (seed, pixel,
// sample) as first_hit_aovs' are, so the beauty's sample streams do not change.
// first_hit: the camera ray's closest hit where it was traced already, else nullptr.
GuideRecord denoise_guide(const Ray& ray, const RenderContext& ctx, uint64_t key,
                          const std::optional<Hit>* first_hit = nullptr);

}  // namespace penumbra
