// Every light a render uses: the scene's punctual lights, one TriangleLight per emissive
// triangle of every instance, and the environment. Chooses a light for a receiver
// (pbrt-v4's LightSampler): uniformly, by power (an alias table, PowerLightSampler), or
// through a light BVH (BVHLightSampler) with the lights it cannot bound (environment,
// directional, emitters moving within the shutter) chosen beside it by power. Maps an
// emissive hit back to its light for MIS.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/lights/environment_light.h"
#include "core/lights/light_bvh.h"
#include "core/lights/triangle_light.h"
#include "core/sampling/alias_table.h"
#include "core/scene/scene.h"

namespace penumbra {

struct SampledLight {
    const Light* light;
    float pmf;  // probability of having chosen it
};

// Auto: Bvh when at least kAutoBvhLights lights have bounds, else Power.
enum class LightSamplerType { Uniform, Power, Bvh, Auto };
constexpr size_t kAutoBvhLights = 64;

// The defaults as measured at equal time (docs/performance.md, "Light sampling at scale"):
// power for the Cornell box's two triangles, the BVH 4.6-7.2x better for 10,000 emitters
// spread over a hall's ceiling (1.7-1.8x worse on a dome, where power is already right);
// solid-angle sampling pays only for large emitters close to the receiver.
struct LightSetOptions {
    LightSamplerType sampler = LightSamplerType::Auto;
    TriangleSampling triangles = TriangleSampling::Area;
};

class LightSet {
public:
    // environment may be null.
    LightSet(const Scene& scene, std::unique_ptr<EnvironmentLight> environment,
             const LightSetOptions& options = {});
    // m_lights points into the set itself: moving keeps the addresses, copying would not.
    LightSet(const LightSet&) = delete;
    LightSet& operator=(const LightSet&) = delete;
    LightSet(LightSet&&) = default;
    LightSet& operator=(LightSet&&) = default;

    // A light for the receiver ref (its geometric normal, or zero in a medium), from one
    // u in [0,1). Empty when no light can reach ref (the BVH knows some cannot).
    std::optional<SampledLight> sample(const ShadingPoint& ref, float u) const;
    // Uniform and power choices depend on u alone and can also return u rescaled to [0,1)
    // within the chosen light's share (pbrt-v4's AliasTable uRemapped; Cycles'
    // light_distribution_sample), so that one sample coordinate both chooses the light
    // and places the point on it. The BVH's choice cannot: use sample(ref, u) there.
    bool remaps_choice() const { return m_type != LightSamplerType::Bvh; }
    // Inline, with the alias table's sampling: it runs on every bounce.
    std::optional<SampledLight> sample_remapped(float u, float* u_remapped) const {
        if (m_type != LightSamplerType::Power) return sample_uniform_remapped(u, u_remapped);
        if (m_alias.empty()) return std::nullopt;
        float pmf;
        const uint32_t i = m_alias.sample(u, &pmf, u_remapped);
        return SampledLight{m_lights[i], pmf};
    }
    // Probability that sample(ref, .) picks this light: the MIS weight of an emitter a
    // BSDF-sampled ray from ref hits needs it at the same ref.
    float pmf(const ShadingPoint& ref, const Light* light) const;
    // Without a receiver: by power, whatever the sampler type.
    std::optional<SampledLight> sample(float u) const;
    float pmf(const Light* light) const;

    // The area light of an emissive triangle, or null.
    const TriangleLight* triangle_light(uint32_t instance, uint32_t mesh, uint32_t prim) const;
    const EnvironmentLight* environment() const { return m_environment.get(); }
    const std::vector<const Light*>& lights() const { return m_lights; }
    size_t triangle_light_count() const { return m_triangles.size(); }
    bool empty() const { return m_lights.empty(); }
    LightSamplerType sampler_type() const { return m_type; }  // Auto resolved
    // The probability of choosing among the lights beside the BVH (0 without the BVH).
    float beside_probability() const { return m_p_beside; }

private:
    // sample_remapped for the uniform choice (the BVH's cannot remap).
    std::optional<SampledLight> sample_uniform_remapped(float u, float* u_remapped) const;
    // Index into m_lights, or -1. O(1) for the lights MIS asks about on every emissive
    // hit: triangle lights by their place in m_triangles, the environment last.
    int64_t index_of(const Light* light) const;

    std::vector<TriangleLight> m_triangles;  // contiguous, never resized after building
    std::unique_ptr<EnvironmentLight> m_environment;
    std::vector<const Light*> m_lights;   // the scene's lights, m_triangles, the environment
    uint32_t m_first_triangle_index = 0;  // of m_triangles[0] in m_lights
    std::unordered_map<const Light*, uint32_t> m_index;
    // Per instance, its range of m_emissive_meshes: (mesh, index of the mesh's first
    // triangle light; prims follow in order). Instances hold few emissive meshes.
    std::vector<uint32_t> m_instance_meshes;  // instances + 1 offsets
    std::vector<std::pair<uint32_t, uint32_t>> m_emissive_meshes;
    LightSamplerType m_type;
    AliasTable m_alias;  // by power over m_lights
    // Bvh: the tree over bounded lights (by index into m_lights), the others by power.
    LightBvh m_bvh;
    std::vector<uint32_t> m_beside;      // indices into m_lights
    std::vector<int32_t> m_beside_slot;  // per light: its index in m_beside, or -1
    AliasTable m_beside_alias;
    float m_p_beside = 0;
};

}  // namespace penumbra
