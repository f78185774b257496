// A material as the scene file describes it: glTF metallic-roughness parameters and
// texture references. Plain data; materials/ turns it into a Bsdf at a hit.
#pragma once

#include <cmath>
#include <string>

#include "core/math/vec.h"

namespace penumbra {

struct TextureRef {
    int texture = -1;  // index into Scene::textures; -1: none
    int texcoord = 0;  // TEXCOORD_n set (KHR_texture_transform's texCoord already applied)
    // KHR_texture_transform: uv' = Translation(offset) Rotation(rotation) Scale(scale) uv,
    // rotation in radians, counter-clockwise in UV space.
    Vec2 offset{0, 0};
    float rotation = 0;
    Vec2 scale{1, 1};

    bool valid() const { return texture >= 0; }
    // The texture coordinates this reference reads at a point with UV sets uv0 and uv1.
    Vec2 uv(Vec2 uv0, Vec2 uv1) const {
        const Vec2 p = texcoord == 1 ? uv1 : uv0;
        const float x = p.x * scale.x, y = p.y * scale.y;
        if (rotation == 0) return {x + offset.x, y + offset.y};
        // The spec's matrix rows: (cos, sin) and (-sin, cos).
        const float c = std::cos(rotation), s = std::sin(rotation);
        return {c * x + s * y + offset.x, -s * x + c * y + offset.y};
    }
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
    // KHR_materials_transmission: the share of the non-metal base that is a rough
    // dielectric instead of diffuse; the texture's R channel scales the factor.
    float transmission = 0;
    TextureRef transmission_texture;

    bool is_emissive() const { return !is_black(emissive) && emissive_strength > 0; }
};

}  // namespace penumbra
