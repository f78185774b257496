#include "core/lights/spot_light.h"

#include <algorithm>
#include <cmath>

#include "core/math/portable_math.h"

namespace penumbra {

SpotLight::SpotLight(Vec3 position, Vec3 direction, Spectrum intensity, float inner_cone,
                     float outer_cone)
    : m_p(position), m_axis(normalize(direction)), m_I(intensity) {
    // KHR_lights_punctual: scale = 1 / max(0.001, cos(inner) - cos(outer)),
    // offset = -cos(outer) * scale, attenuation = clamp(cd * scale + offset, 0, 1)^2.
    m_cos_outer = portable_cos(outer_cone);
    m_scale = 1.0f / std::max(0.001f, portable_cos(inner_cone) - m_cos_outer);
    m_offset = -m_cos_outer * m_scale;
}

float SpotLight::falloff(float cos_theta) const {
    const float a = std::clamp(cos_theta * m_scale + m_offset, 0.0f, 1.0f);
    return a * a;
}

std::optional<LightSample> SpotLight::sample_Li(const ShadingPoint& ref, Vec2, float) const {
    const Vec3 d = m_p - ref.p;
    const float dist2 = length_squared(d);
    if (!(dist2 > 0)) return std::nullopt;
    const float dist = std::sqrt(dist2);
    const Vec3 wi = d / dist;
    const float att = falloff(dot(-wi, m_axis));
    if (att <= 0 || is_black(m_I)) return std::nullopt;
    return LightSample{wi, dist, m_I * (att / dist2), 1.0f, true, m_p};
}

float SpotLight::power() const {
    // Upper bound: the full outer cone at full intensity.
    return luminance(m_I) * 2 * kPi * (1 - m_cos_outer);
}

std::optional<LightBounds> SpotLight::bounds() const {
    LightBounds b;
    b.lo = b.hi = m_p;
    // Weighed like a point light of the same intensity, so the tree compares the light
    // arriving at a receiver inside the cone (pbrt-v4 does the same).
    b.phi = 4 * kPi * luminance(m_I);
    b.w = m_axis;
    // The outer cone, widened by 1e-3 rad so rounding at its edge never zeroes a
    // receiver the falloff still reaches; no spread beyond it (theta_e = 0).
    b.cos_theta_o =
        portable_cos(std::min(std::acos(std::clamp(m_cos_outer, -1.0f, 1.0f)) + 1e-3f, kPi));
    b.cos_theta_e = 1;
    return b;
}

}  // namespace penumbra
