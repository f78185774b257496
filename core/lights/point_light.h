// KHR_lights_punctual point light: intensity I (candela) emitted equally in all
// directions from a point; irradiance falls off as 1/d^2.
#pragma once

#include "core/lights/light.h"

namespace penumbra {

class PointLight final : public Light {
public:
    PointLight(Vec3 position, Spectrum intensity) : m_p(position), m_I(intensity) {}
    std::optional<LightSample> sample_Li(const ShadingPoint& ref, Vec2 u,
                                         float time) const override;
    float pdf_Li(const ShadingPoint&, Vec3, float) const override { return 0; }
    float power() const override { return 4 * kPi * luminance(m_I); }
    bool is_delta() const override { return true; }
    // A point emitting over the whole sphere.
    std::optional<LightBounds> bounds() const override {
        LightBounds b;
        b.lo = b.hi = m_p;
        b.phi = power();
        b.cos_theta_o = -1;
        return b;
    }
    std::string describe() const override { return "point"; }

private:
    Vec3 m_p;
    Spectrum m_I;
};

}  // namespace penumbra
