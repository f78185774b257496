// Per material, the BSDF that shade() would build at every hit, built once per render
// where nothing it depends on varies over the surface: no texture feeds it, no vertex
// colour tints it, and the model is an opaque one (Lambertian or the glTF BRDF without
// layers, films or anisotropy). shade() then refers to the model instead of working out
// its parameters and constructing it (the albedo-table row, the layer's E_avg) at each
// hit: on scenes/glossy.gltf that saves about 7% of the render.
#pragma once

#include <cstdint>
#include <vector>

#include "core/math/vec.h"
#include "materials/material.h"

namespace penumbra {

class BsdfPrototypes {
public:
    // options: the distribution and layering the prototypes follow (shade() passes its
    // own options to find(), which rejects others).
    BsdfPrototypes(const Scene& scene, const MaterialOptions& options);
    // The model for a hit on material whose vertex colour is color, under options; null
    // where shade() must build it: the material varies, the vertex colour is not white,
    // or options ask for another distribution or layering, or for a least roughness
    // above the material's (the path tracer's regularization).
    const BsdfStorage* find(uint32_t material, const Vec4& color,
                            const MaterialOptions& options) const {
        if (material >= m_entries.size()) return nullptr;
        const Entry& e = m_entries[material];
        if (!e.valid || !(options.min_roughness <= e.roughness) ||
            options.gltf_distribution != m_distribution || options.gltf_layering != m_layering)
            return nullptr;
        if (color.x != 1 || color.y != 1 || color.z != 1) return nullptr;
        return &e.bsdf;
    }
    // How many materials have one (for tests and stats).
    size_t count() const;
    // Whether shade() gives material's hits a BSDF that depends on nothing but the
    // material: the condition for a prototype.
    static bool uniform(const MaterialDesc& m);

private:
    struct Entry {
        bool valid = false;
        float roughness = 0;  // the material's, as shade() clamps it
        BsdfStorage bsdf;
    };
    std::vector<Entry> m_entries;
    MicrofacetType m_distribution;
    GltfLayering m_layering;
};

}  // namespace penumbra
