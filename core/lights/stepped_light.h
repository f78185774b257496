// A punctual light whose colour, intensity, cone, visibility or place changes within the
// shutter (KHR_animation_pointer, KHR_node_visibility, node animation): the light at K
// time steps across it, a sample at normalized time u taking the nearest step (the
// composite trapezoid rule, as for animated materials: Scene::material_steps).
#pragma once

#include <memory>
#include <vector>

#include "core/lights/light.h"

namespace penumbra {

class SteppedLight final : public Light {
public:
    // steps[k]: the light at normalized shutter time k / (K - 1), K >= 2; nullptr where it
    // is hidden. At least one step is a light, and all are delta or none.
    explicit SteppedLight(std::vector<std::unique_ptr<Light>> steps);

    std::optional<LightSample> sample_Li(const ShadingPoint& ref, Vec2 u,
                                         float time) const override;
    float pdf_Li(const ShadingPoint& ref, Vec3 wi, float time) const override;
    // The mean over the steps: only chooses among lights.
    float power() const override { return m_power; }
    bool is_delta() const override { return m_delta; }
    // Sampled beside the light tree, as moving emitters are.
    std::optional<LightBounds> bounds() const override { return std::nullopt; }
    std::string describe() const override { return m_describe; }
    // The light at normalized time `time`; nullptr while hidden.
    const Light* at(float time) const;

private:
    std::vector<std::unique_ptr<Light>> m_steps;
    float m_power = 0;
    bool m_delta = true;
    std::string m_describe;
};

}  // namespace penumbra
