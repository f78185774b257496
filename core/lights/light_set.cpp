#include "core/lights/light_set.h"

#include "core/scene/emission.h"

namespace penumbra {

namespace {
uint64_t key(uint32_t instance, uint32_t mesh) { return (uint64_t(instance) << 32) | mesh; }
}  // namespace

LightSet::LightSet(const Scene& scene, std::unique_ptr<EnvironmentLight> environment)
    : m_environment(std::move(environment)) {
    // Mean emission per material, computed once (textures can be large).
    std::vector<std::optional<Spectrum>> mean_Le(scene.materials.size() + 1);
    for (uint32_t ii = 0; ii < scene.instances.size(); ++ii) {
        const Object& obj = scene.objects[scene.instances[ii].object];
        for (uint32_t mi : obj.meshes) {
            const TriangleMesh& mesh = scene.meshes[mi];
            const MaterialDesc& mat = scene.material(mesh.material);
            if (!mat.is_emissive()) continue;
            // Emitters that move within the shutter are sampled where they are at the
            // ray's time (TriangleLight::placed).
            auto& mean = mean_Le[mesh.material + 1];
            if (!mean)
                mean = mat.emissive * mat.emissive_strength * mean_emission_texture(scene, mat);
            m_first_triangle[key(ii, mi)] = static_cast<uint32_t>(m_triangles.size());
            for (uint32_t p = 0; p < mesh.triangle_count(); ++p)
                m_triangles.push_back(std::make_unique<TriangleLight>(scene, ii, mi, p, *mean));
        }
    }
    for (const auto& l : scene.lights) m_lights.push_back(l.get());
    for (const auto& t : m_triangles) m_lights.push_back(t.get());
    if (m_environment) m_lights.push_back(m_environment.get());

    std::vector<float> power;
    power.reserve(m_lights.size());
    for (uint32_t i = 0; i < m_lights.size(); ++i) {
        m_index[m_lights[i]] = i;
        power.push_back(m_lights[i]->power());
    }
    m_alias = AliasTable(power);
}

std::optional<SampledLight> LightSet::sample(float u) const {
    if (m_alias.empty()) return std::nullopt;
    float pmf;
    const uint32_t i = m_alias.sample(u, &pmf);
    return SampledLight{m_lights[i], pmf};
}

float LightSet::pmf(const Light* light) const {
    if (m_alias.empty()) return 0;
    const auto it = m_index.find(light);
    return it == m_index.end() ? 0.0f : m_alias.pmf(it->second);
}

const TriangleLight* LightSet::triangle_light(uint32_t instance, uint32_t mesh,
                                              uint32_t prim) const {
    const auto it = m_first_triangle.find(key(instance, mesh));
    if (it == m_first_triangle.end()) return nullptr;
    return m_triangles[it->second + prim].get();
}

}  // namespace penumbra
