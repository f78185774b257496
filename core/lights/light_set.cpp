#include "core/lights/light_set.h"

#include <algorithm>
#include <stdexcept>

#include "core/error.h"
#include "core/scene/emission.h"

namespace penumbra {

namespace {
constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

// A material's mean emitted radiance, for the power estimate; for one that changes
// within the shutter, averaged over its time steps.
Spectrum mean_emission(const Scene& scene, int material) {
    auto of = [&](int index) {
        const MaterialDesc& m = scene.material(index);
        return m.emissive * m.emissive_strength * mean_emission_texture(scene, m);
    };
    if (material < 0 || size_t(material) >= scene.material_steps.size() ||
        scene.material_steps[size_t(material)].empty())
        return of(material);
    Spectrum sum(0);
    for (int step : scene.material_steps[size_t(material)]) sum += of(step);
    return sum / float(scene.material_steps[size_t(material)].size());
}
}  // namespace

LightSet::LightSet(const Scene& scene, std::unique_ptr<EnvironmentLight> environment,
                   const LightSetOptions& options)
    : m_environment(std::move(environment)), m_type(options.sampler) {
    // Mean emission per material, computed once (textures can be large).
    std::vector<std::optional<Spectrum>> mean_Le(scene.materials.size() + 1);
    auto emissive = [&](uint32_t mi) { return scene.may_emit(scene.meshes[mi].material); };
    size_t count = 0;
    for (const Instance& inst : scene.instances)
        for (uint32_t mi : scene.objects[inst.object].meshes)
            if (emissive(mi)) count += scene.meshes[mi].triangle_count();
    m_triangles.reserve(count);  // the lights' addresses must not move
    m_instance_meshes.reserve(scene.instances.size() + 1);
    for (uint32_t ii = 0; ii < scene.instances.size(); ++ii) {
        m_instance_meshes.push_back(static_cast<uint32_t>(m_emissive_meshes.size()));
        const Object& obj = scene.objects[scene.instances[ii].object];
        for (uint32_t mi : obj.meshes) {
            if (!emissive(mi)) continue;
            const TriangleMesh& mesh = scene.meshes[mi];
            // Emitters that move within the shutter are sampled where they are at the
            // ray's time (TriangleLight::placed).
            auto& mean = mean_Le[mesh.material + 1];
            if (!mean) mean = mean_emission(scene, mesh.material);
            m_emissive_meshes.emplace_back(mi, static_cast<uint32_t>(m_triangles.size()));
            for (uint32_t p = 0; p < mesh.triangle_count(); ++p)
                m_triangles.emplace_back(scene, ii, mi, p, *mean, options.triangles);
        }
    }
    m_instance_meshes.push_back(static_cast<uint32_t>(m_emissive_meshes.size()));
    for (const auto& l : scene.lights) m_lights.push_back(l.get());
    m_first_triangle_index = static_cast<uint32_t>(m_lights.size());
    for (const TriangleLight& t : m_triangles) m_lights.push_back(&t);
    if (m_environment) m_lights.push_back(m_environment.get());

    std::vector<float> power;
    power.reserve(m_lights.size());
    for (uint32_t i = 0; i < m_lights.size(); ++i) {
        m_index[m_lights[i]] = i;
        power.push_back(m_lights[i]->power());
    }
    m_alias = AliasTable(power);
    if (m_type == LightSamplerType::Auto) {
        size_t bounded = 0;
        for (const Light* l : m_lights) bounded += l->bounds().has_value();
        m_type = bounded >= kAutoBvhLights ? LightSamplerType::Bvh : LightSamplerType::Power;
    }
    if (m_type != LightSamplerType::Bvh) return;

    std::vector<std::pair<uint32_t, LightBounds>> bounded;
    std::vector<float> beside_power;
    m_beside_slot.assign(m_lights.size(), -1);
    for (uint32_t i = 0; i < m_lights.size(); ++i) {
        if (const std::optional<LightBounds> b = m_lights[i]->bounds()) {
            bounded.emplace_back(i, *b);  // zero power: left out by the tree, never chosen
        } else {
            m_beside_slot[i] = static_cast<int32_t>(m_beside.size());
            m_beside.push_back(i);
            beside_power.push_back(power[i]);
        }
    }
    m_bvh = LightBvh(std::move(bounded));
    m_beside_alias = AliasTable(beside_power);
    // As pbrt-v4 gives its infinite lights a fixed share: half when there is a tree too.
    // A fixed probability keeps the choice independent of the receiver's position.
    m_p_beside = m_beside_alias.empty() ? 0.0f : m_bvh.empty() ? 1.0f : 0.5f;
}

std::optional<SampledLight> LightSet::sample(const ShadingPoint& ref, float u) const {
    switch (m_type) {
        case LightSamplerType::Uniform: {
            if (m_lights.empty()) return std::nullopt;
            const size_t n = m_lights.size();
            const size_t i = std::min(size_t(u * n), n - 1);
            return SampledLight{m_lights[i], 1.0f / n};
        }
        case LightSamplerType::Power:
            return sample(u);
        case LightSamplerType::Bvh:
        case LightSamplerType::Auto:  // resolved in the constructor
            break;
    }
    if (u < m_p_beside) {
        float pmf;
        const uint32_t k = m_beside_alias.sample(std::min(u / m_p_beside, kOneMinusEpsilon), &pmf);
        return SampledLight{m_lights[m_beside[k]], m_p_beside * pmf};
    }
    const float u_tree = std::min((u - m_p_beside) / (1 - m_p_beside), kOneMinusEpsilon);
    const auto chosen = m_bvh.sample(ref.p, ref.n, u_tree);
    if (!chosen) return std::nullopt;
    return SampledLight{m_lights[chosen->first], (1 - m_p_beside) * chosen->second};
}

std::optional<SampledLight> LightSet::sample_uniform_remapped(float u, float* u_remapped) const {
    CHECK(remaps_choice());
    if (m_lights.empty()) return std::nullopt;
    const size_t n = m_lights.size();
    const size_t i = std::min(size_t(u * n), n - 1);
    *u_remapped = std::min(u * n - float(i), kOneMinusEpsilon);
    return SampledLight{m_lights[i], 1.0f / n};
}

int64_t LightSet::index_of(const Light* light) const {
    // Compared as addresses: a light that is not in m_triangles is never cast to one.
    const auto a = reinterpret_cast<uintptr_t>(light);
    const auto first = reinterpret_cast<uintptr_t>(static_cast<const Light*>(m_triangles.data()));
    if (a >= first && a < first + m_triangles.size() * sizeof(TriangleLight))
        return m_first_triangle_index + (a - first) / sizeof(TriangleLight);
    if (light && light == m_environment.get()) return int64_t(m_lights.size()) - 1;
    const auto it = m_index.find(light);
    return it == m_index.end() ? -1 : int64_t(it->second);
}

float LightSet::pmf(const ShadingPoint& ref, const Light* light) const {
    const int64_t i = index_of(light);
    if (i < 0) return 0;
    const auto index = static_cast<uint32_t>(i);
    switch (m_type) {
        case LightSamplerType::Uniform:
            return 1.0f / m_lights.size();
        case LightSamplerType::Power:
            return m_alias.empty() ? 0.0f : m_alias.pmf(index);
        case LightSamplerType::Bvh:
        case LightSamplerType::Auto:  // resolved in the constructor
            break;
    }
    if (const int32_t slot = m_beside_slot[index]; slot >= 0)
        return m_beside_alias.empty() ? 0.0f : m_p_beside * m_beside_alias.pmf(uint32_t(slot));
    return (1 - m_p_beside) * m_bvh.pmf(ref.p, ref.n, index);
}

std::optional<SampledLight> LightSet::sample(float u) const {
    if (m_alias.empty()) return std::nullopt;
    float pmf;
    const uint32_t i = m_alias.sample(u, &pmf);
    return SampledLight{m_lights[i], pmf};
}

float LightSet::pmf(const Light* light) const {
    if (m_alias.empty()) return 0;
    const int64_t i = index_of(light);
    return i < 0 ? 0.0f : m_alias.pmf(static_cast<uint32_t>(i));
}

const TriangleLight* LightSet::triangle_light(uint32_t instance, uint32_t mesh,
                                              uint32_t prim) const {
    if (instance + 1 >= m_instance_meshes.size()) return nullptr;
    for (uint32_t k = m_instance_meshes[instance]; k < m_instance_meshes[instance + 1]; ++k)
        if (m_emissive_meshes[k].first == mesh)
            return &m_triangles[m_emissive_meshes[k].second + prim];
    return nullptr;
}

}  // namespace penumbra
