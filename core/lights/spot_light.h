// KHR_lights_punctual spot light: a point light restricted to a cone around its -Z axis,
// with the spec's smooth falloff between the inner and outer cone angles.
#pragma once

#include "core/lights/light.h"

namespace penumbra {

class SpotLight final : public Light {
public:
    // direction: unit axis of the cone (the node's -Z in world space).
    SpotLight(Vec3 position, Vec3 direction, Spectrum intensity, float inner_cone,
              float outer_cone);
    std::optional<LightSample> sample_Li(const ShadingPoint& ref, Vec2 u,
                                         float time) const override;
    float pdf_Li(const ShadingPoint&, Vec3, float) const override { return 0; }
    float power() const override;
    bool is_delta() const override { return true; }
    // A point emitting inside its outer cone.
    std::optional<LightBounds> bounds() const override;
    std::string describe() const override { return "spot"; }
    // The spec's angular attenuation for a direction from the light with
    // cos(angle to axis) = cos_theta, in [0, 1].
    float falloff(float cos_theta) const;

private:
    Vec3 m_p, m_axis;
    Spectrum m_I;
    float m_cos_outer, m_scale, m_offset;
};

}  // namespace penumbra
