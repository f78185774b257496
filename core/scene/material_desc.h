// A material as the scene file describes it: glTF metallic-roughness parameters and
// texture references. Plain data; materials/ turns it into a Bsdf at a hit.
#pragma once

#include <string>

#include "core/math/vec.h"

namespace penumbra {

struct TextureRef {
    int texture = -1;  // index into Scene::textures; -1: none
    int texcoord = 0;  // TEXCOORD_n set
    bool valid() const { return texture >= 0; }
};

enum class AlphaMode { Opaque, Mask, Blend };

struct MaterialDesc {
    std::string name;
    // pbrMetallicRoughness (defaults are the glTF spec's).
    Vec4 base_color{1, 1, 1, 1};
    TextureRef base_color_texture;
    float metallic = 1;
    float roughness = 1;
    TextureRef metallic_roughness_texture;  // B: metallic, G: roughness
    TextureRef normal_texture;
    float normal_scale = 1;
    TextureRef occlusion_texture;
    float occlusion_strength = 1;
    Spectrum emissive{0, 0, 0};
    TextureRef emissive_texture;
    float emissive_strength = 1;  // KHR_materials_emissive_strength
    AlphaMode alpha_mode = AlphaMode::Opaque;
    float alpha_cutoff = 0.5f;
    bool double_sided = false;
    // KHR_materials_ior and KHR_materials_specular.
    float ior = 1.5f;
    float specular = 1;
    Spectrum specular_color{1, 1, 1};

    bool is_emissive() const { return !is_black(emissive) && emissive_strength > 0; }
};

}  // namespace penumbra
