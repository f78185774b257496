#include "core/lights/directional_light.h"

#include <limits>

namespace penumbra {

std::optional<LightSample> DirectionalLight::sample_Li(const ShadingPoint&, Vec2,
                                                       float) const {
    if (is_black(m_E)) return std::nullopt;
    return LightSample{-m_w, std::numeric_limits<float>::infinity(), m_E, 1.0f, true,
                       {}};  // no point: at infinity
}

}  // namespace penumbra
