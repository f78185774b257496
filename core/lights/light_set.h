// Every light a render uses: the scene's punctual lights, one TriangleLight per emissive
// triangle of every instance that does not move within the shutter, and the environment. Chooses lights in proportion to their
// power with an alias table (PBRT's PowerLightSampler), and maps an emissive hit back
// to its light for MIS.
#pragma once

#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

#include "core/lights/environment_light.h"
#include "core/lights/triangle_light.h"
#include "core/sampling/alias_table.h"
#include "core/scene/scene.h"

namespace penumbra {

struct SampledLight {
    const Light* light;
    float pmf;  // probability of having chosen it
};

class LightSet {
public:
    // environment may be null.
    LightSet(const Scene& scene, std::unique_ptr<EnvironmentLight> environment);

    std::optional<SampledLight> sample(float u) const;
    // Probability that sample() picks this light.
    float pmf(const Light* light) const;
    // The area light of an emissive triangle, or null.
    const TriangleLight* triangle_light(uint32_t instance, uint32_t mesh, uint32_t prim) const;
    const EnvironmentLight* environment() const { return m_environment.get(); }
    const std::vector<const Light*>& lights() const { return m_lights; }
    size_t triangle_light_count() const { return m_triangles.size(); }
    bool empty() const { return m_lights.empty(); }

private:
    std::vector<std::unique_ptr<TriangleLight>> m_triangles;
    std::unique_ptr<EnvironmentLight> m_environment;
    std::vector<const Light*> m_lights;
    std::unordered_map<const Light*, uint32_t> m_index;
    // (instance, mesh) -> index of the mesh's first triangle light; prims follow in order.
    std::unordered_map<uint64_t, uint32_t> m_first_triangle;
    AliasTable m_alias;
};

}  // namespace penumbra
