#include "core/lights/stepped_light.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace penumbra {

SteppedLight::SteppedLight(std::vector<std::unique_ptr<Light>> steps) : m_steps(std::move(steps)) {
    if (m_steps.size() < 2) throw std::invalid_argument("SteppedLight needs two steps or more");
    const Light* first = nullptr;
    double sum = 0;
    for (const auto& l : m_steps) {
        if (!l) continue;
        if (!first) first = l.get();
        if (l->is_delta() != first->is_delta())
            throw std::invalid_argument("SteppedLight steps mix delta and area lights");
        sum += l->power();
    }
    if (!first) throw std::invalid_argument("SteppedLight is hidden at every step");
    m_power = float(sum / double(m_steps.size()));
    m_delta = first->is_delta();
    m_describe = first->describe() + " (animated)";
}

const Light* SteppedLight::at(float time) const {
    const float k = std::round(std::clamp(time, 0.0f, 1.0f) * float(m_steps.size() - 1));
    return m_steps[size_t(k)].get();
}

std::optional<LightSample> SteppedLight::sample_Li(const ShadingPoint& ref, Vec2 u,
                                                   float time) const {
    const Light* l = at(time);
    return l ? l->sample_Li(ref, u, time) : std::nullopt;
}

float SteppedLight::pdf_Li(const ShadingPoint& ref, Vec3 wi, float time) const {
    const Light* l = at(time);
    return l ? l->pdf_Li(ref, wi, time) : 0.0f;
}

}  // namespace penumbra
