// Default lighting for scenes that bring too little light of their own: a key and a fill
// directional light from the camera's side and a dim uniform environment, and the rule
// behind --default-light auto that decides whether a scene's emitters already light it.
#pragma once

#include <memory>
#include <string>

#include "core/lights/environment_light.h"
#include "core/scene/scene.h"

namespace penumbra {

enum class DefaultLightMode {
    Auto,  // only when the scene has no lights, no environment and no substantial emitters
    On,    // always (key and fill; the environment only where none was given)
    Off,   // never
};

// Irradiance (W/m^2) of the key and the fill light, and the environment's radiance.
constexpr float kDefaultKeyIrradiance = 2.5f;
constexpr float kDefaultFillIrradiance = 0.6f;
constexpr float kDefaultEnvironmentRadiance = 0.3f;

// The scene's emissive triangles (placed at shutter open), emission = factor x strength x
// the emission texture's mean, as luminance (Rec.709 weights).
struct EmitterSummary {
    double area = 0;   // m^2, world space
    double power = 0;  // W, from one side: pi x sum(area x mean luminance)
    // Area-weighted mean emitted radiance: power / (pi area).
    double mean_radiance() const;
};
EmitterSummary summarize_emitters(const Scene& scene);

struct LightingChoice {
    bool add_defaults = false;
    std::string reason;  // one line for the notice: what lights the scene, and why
};

// The rule (docs/conventions.md, "Default lighting"): with Auto, a scene without punctual
// lights and without an environment (has_environment: --env, --env-color) gets the default
// lighting unless its emitters count as lighting it: their mean radiance is at least that
// of a white surface facing the key and fill lights, (2.5 + 0.6) / pi, so they are light
// sources rather than glowing decals, and their power is at least 1% of what the key and
// fill deliver to the scene's bounding sphere, (2.5 + 0.6) pi R^2, so they are not a
// speck in a large scene.
LightingChoice choose_lighting(DefaultLightMode mode, const Scene& scene, bool has_environment);

// Adds the key light (from the camera's upper right) and the fill (from its left) to
// scene.lights; returns the dim environment to use when the scene has none.
std::unique_ptr<EnvironmentLight> add_default_lights(Scene& scene, const CameraDesc& camera);

}  // namespace penumbra
