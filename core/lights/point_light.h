// KHR_lights_punctual point light: intensity I (candela) emitted equally in all
// directions from a point; irradiance falls off as 1/d^2.
#pragma once

#include <cmath>

#include "core/lights/light.h"

namespace penumbra {

class PointLight final : public Light {
public:
    PointLight(Vec3 position, Spectrum intensity) : Light(true), m_p(position), m_I(intensity) {}
    // Inline, for sample_light_Li below.
    std::optional<LightSample> sample_Li(const ShadingPoint& ref, Vec2, float) const override {
        const Vec3 d = m_p - ref.p;
        const float dist2 = length_squared(d);
        if (!(dist2 > 0) || is_black(m_I)) return std::nullopt;
        const float dist = std::sqrt(dist2);
        return LightSample{d / dist, dist, m_I / dist2, 1.0f, true, m_p};
    }
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

// light.sample_Li(ref, u, time), with a point light's called directly and inlined: the
// commonest delta light, sampled at every path vertex of scenes lit by one, where the
// virtual call and its result's round trip through memory cost about 20 instructions.
// The same values, bit for bit.
inline std::optional<LightSample> sample_light_Li(const Light& light, const ShadingPoint& ref,
                                                  Vec2 u, float time) {
    if (light.is_point())
        return static_cast<const PointLight&>(light).PointLight::sample_Li(ref, u, time);
    return light.sample_Li(ref, u, time);
}

}  // namespace penumbra
