// KHR_lights_punctual directional light: parallel light along the node's -Z with
// illuminance E (lux) on a surface facing it.
#pragma once

#include "core/lights/light.h"

namespace penumbra {

class DirectionalLight final : public Light {
public:
    // direction: the direction light travels (the node's -Z in world space).
    // scene_radius: bounds the power estimate used to choose among lights.
    DirectionalLight(Vec3 direction, Spectrum irradiance, float scene_radius)
        : m_w(normalize(direction)), m_E(irradiance), m_radius(scene_radius) {}
    std::optional<LightSample> sample_Li(const ShadingPoint& ref, Vec2 u,
                                         float time) const override;
    float pdf_Li(const ShadingPoint&, Vec3, float) const override { return 0; }
    float power() const override { return kPi * m_radius * m_radius * luminance(m_E); }
    bool is_delta() const override { return true; }
    std::string describe() const override { return "directional"; }

private:
    Vec3 m_w;
    Spectrum m_E;
    float m_radius;
};

}  // namespace penumbra
