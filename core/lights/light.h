// Light sources, in radiometric units: radiant intensity (W/sr) for point and spot lights,
// irradiance (W/m^2) for directional ones, radiance for emitters and the environment. glTF's
// candela and lux are divided by 683 lm/W at load (light_units.h); emission stays radiance.
#pragma once

#include <optional>
#include <string>

#include "core/lights/light_bounds.h"
#include "core/math/vec.h"

namespace penumbra {

// The receiving point of a light query.
struct ShadingPoint {
    Vec3 p;
    Vec3 n;  // geometric normal, or zero for a point in a medium
};

// Fields in this order so that the two 16-byte stores a light writes the record with
// (wi + dist, Li + pdf) each hold whole fields, and a later 8-byte read of wi.xy comes from
// one store instead of waiting for two to reach memory.
struct LightSample {
    Vec3 wi;           // unit direction from the receiver towards the light
    float dist = 0;    // distance to the light sample (infinity for directional)
    Spectrum Li;       // incident radiance (or intensity / d^2 for a delta light)
    float pdf = 0;     // solid angle density; 1 for delta lights
    bool delta = false;
    // The point sampled on the light, where dist is finite: shadow rays aim at it
    // (spawn_ray_to), so that their direction waits on the origin's offset only, not on
    // the square root and division that give wi and dist.
    Vec3 p;
};

class Light {
public:
    virtual ~Light() = default;
    // Samples incident light at ref. u in [0,1)^2, time in [0,1]. Empty when the light
    // cannot reach ref (behind a spot cone, zero intensity).
    virtual std::optional<LightSample> sample_Li(const ShadingPoint& ref, Vec2 u,
                                                 float time) const = 0;
    // Solid-angle density of sample_Li choosing wi at time (as sample_Li's); 0 for delta
    // lights.
    virtual float pdf_Li(const ShadingPoint& ref, Vec3 wi, float time) const = 0;
    // Total emitted power, for choosing among lights.
    virtual float power() const = 0;
    virtual bool is_delta() const = 0;
    // Where the light is and which way it emits, for a light BVH; empty for lights at
    // infinity and for emitters that move within the shutter (sampled beside the tree).
    virtual std::optional<LightBounds> bounds() const { return std::nullopt; }
    virtual std::string describe() const = 0;
    // Whether this is a PointLight: the light sample of a path vertex calls its sample_Li
    // directly (sample_light_Li in point_light.h).
    bool is_point() const { return m_point; }

protected:
    Light() = default;
    explicit Light(bool point) : m_point(point) {}

private:
    bool m_point = false;
};

}  // namespace penumbra
