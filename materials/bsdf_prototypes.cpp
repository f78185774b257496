#include "materials/bsdf_prototypes.h"

#include <algorithm>

namespace penumbra {

bool BsdfPrototypes::uniform(const MaterialDesc& m) {
    // Every input of shade()'s BSDF that a texture, the path or the frame can change.
    // Normal and emissive maps, occlusion and the base colour's alpha do not reach the
    // model; a transmitting material's does (the IOR on each side, dispersion).
    return !m.unlit && !m.specular_glossiness && !m.base_color_texture.valid() &&
           !m.metallic_roughness_texture.valid() && !m.specular_texture.valid() &&
           !m.specular_color_texture.valid() && m.transmission == 0 && m.clearcoat == 0 &&
           max_component(m.sheen_color) <= 0 && m.iridescence == 0 &&
           m.anisotropy_strength == 0 && m.diffuse_transmission == 0;
}

BsdfPrototypes::BsdfPrototypes(const Scene& scene, const MaterialOptions& options)
    : m_entries(scene.materials.size()),
      m_distribution(options.gltf_distribution),
      m_layering(options.gltf_layering) {
    // shade() itself builds each prototype, at a point that stands for any hit: white
    // vertex colour, no textures to read, seen from the front.
    MaterialOptions plain = options;
    plain.min_roughness = 0;
    plain.prototypes = nullptr;
    for (uint32_t i = 0; i < scene.materials.size(); ++i) {
        const MaterialDesc& m = scene.materials[i];
        if (!uniform(m)) continue;
        SurfacePoint sp;
        sp.material = i;
        sp.ng = sp.ns = Vec3(0, 0, 1);
        sp.ng_is_front = true;
        sp.color = Vec4(1, 1, 1, 1);
        Entry& e = m_entries[i];
        e.bsdf = shade(scene, sp, Vec3(0, 0, 1), plain).bsdf;
        e.roughness = std::clamp(m.roughness, 0.0f, 1.0f);
        e.valid = e.bsdf.get() != nullptr;
    }
}

size_t BsdfPrototypes::count() const {
    return size_t(std::count_if(m_entries.begin(), m_entries.end(),
                                [](const Entry& e) { return e.valid; }));
}

}  // namespace penumbra
