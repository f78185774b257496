#include "core/lights/point_light.h"

#include <cmath>

namespace penumbra {

std::optional<LightSample> PointLight::sample_Li(const ShadingPoint& ref, Vec2,
                                                 float) const {
    const Vec3 d = m_p - ref.p;
    const float dist2 = length_squared(d);
    if (!(dist2 > 0) || is_black(m_I)) return std::nullopt;
    const float dist = std::sqrt(dist2);
    return LightSample{d / dist, dist, m_I / dist2, 1.0f, true};
}

}  // namespace penumbra
