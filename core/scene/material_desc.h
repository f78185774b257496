// A material as the scene file describes it: glTF metallic-roughness parameters and
// texture references. Plain data; materials/ turns it into a Bsdf at a hit.
#pragma once

#include <cmath>
#include <string>

#include "core/math/portable_math.h"
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
    // A footprint w0 (w1) wide in UV set 0 (1) as a width in the coordinates read.
    float width(float w0, float w1) const {
        return (texcoord == 1 ? w1 : w0) * std::sqrt(std::abs(scale.x * scale.y));
    }
    // The texture coordinates this reference reads at a point with UV sets uv0 and uv1.
    Vec2 uv(Vec2 uv0, Vec2 uv1) const {
        const Vec2 p = texcoord == 1 ? uv1 : uv0;
        const float x = p.x * scale.x, y = p.y * scale.y;
        if (rotation == 0) return {x + offset.x, y + offset.y};
        // The spec's matrix rows: (cos, sin) and (-sin, cos).
        const float c = portable_cos(rotation), s = portable_sin(rotation);
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
    // KHR_materials_specular textures: A scales specularFactor, RGB (sRGB) the colour.
    TextureRef specular_texture;
    TextureRef specular_color_texture;

    // KHR_materials_clearcoat: a second GGX lobe (IOR 1.5) over everything else, with its
    // own roughness and normal map. Textures: clearcoat R, roughness G.
    float clearcoat = 0;
    TextureRef clearcoat_texture;
    float clearcoat_roughness = 0;
    TextureRef clearcoat_roughness_texture;
    TextureRef clearcoat_normal_texture;
    float clearcoat_normal_scale = 1;

    // KHR_materials_sheen: Charlie sheen over the base. Colour texture RGB (sRGB),
    // roughness texture A.
    Spectrum sheen_color{0, 0, 0};
    TextureRef sheen_color_texture;
    float sheen_roughness = 0;
    TextureRef sheen_roughness_texture;

    // KHR_materials_volume: the inside of a closed mesh is a homogeneous absorbing medium
    // (Beer-Lambert with attenuation_color reached at attenuation_distance). thickness 0:
    // thin-walled (no medium). Thickness texture G.
    float thickness = 0;
    TextureRef thickness_texture;
    float attenuation_distance = INFINITY;
    Spectrum attenuation_color{1, 1, 1};

    // KHR_materials_iridescence: a thin film (Belcour & Barla 2017) over the base.
    // Factor texture R, thickness texture G (mixes thickness min to max, in nm).
    float iridescence = 0;
    TextureRef iridescence_texture;
    float iridescence_ior = 1.3f;
    float iridescence_thickness_min = 100;
    float iridescence_thickness_max = 400;
    TextureRef iridescence_thickness_texture;

    // KHR_materials_anisotropy: strength in [0, 1], rotation (radians, counter-clockwise
    // from the tangent); texture RG: direction in tangent space ([0,1] -> [-1,1]), B:
    // strength.
    float anisotropy_strength = 0;
    float anisotropy_rotation = 0;
    TextureRef anisotropy_texture;

    // KHR_materials_dispersion: 20 / Abbe number; 0 is no dispersion.
    float dispersion = 0;

    // KHR_materials_diffuse_transmission: the share of the diffuse base that is
    // transmitted (Lambertian, to the other side). Factor texture A, colour texture RGB
    // (sRGB).
    float diffuse_transmission = 0;
    TextureRef diffuse_transmission_texture;
    Spectrum diffuse_transmission_color{1, 1, 1};
    TextureRef diffuse_transmission_color_texture;

    // KHR_materials_unlit: the surface shows base colour (factor x texture x vertex
    // colour) as emitted radiance and reflects nothing.
    bool unlit = false;

    // KHR_materials_pbrSpecularGlossiness (archived): base_color/_texture hold the diffuse
    // colour, specular_color the f0 colour (f90 1), roughness 1 - glossiness; the texture
    // is RGB specular (sRGB), A glossiness. metallic is 0.
    bool specular_glossiness = false;
    TextureRef specular_glossiness_texture;

    bool is_emissive() const { return !is_black(emissive) && emissive_strength > 0; }
};

}  // namespace penumbra
