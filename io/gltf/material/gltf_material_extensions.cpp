// Each function follows its spec in KhronosGroup/glTF extensions/2.0/Khronos/<name>/
// README.md and its schema: property names, defaults, ranges and texture channels
// (recorded beside the fields in core/scene/material_desc.h). Only the colour textures
// (sheen colour, diffuse transmission colour) are sRGB.
#include "io/gltf/material/gltf_material_extensions.h"

#include "io/gltf/material/gltf_material_json.h"

namespace penumbra {

namespace {

constexpr JsonRange kPositive{0, INFINITY, true};
constexpr JsonRange kAtLeastOne{1, INFINITY};

// The extension object `name` of material gm and its element path.
struct Extension {
    const tinygltf::Value& obj;
    std::string el;
};

Extension find(const tinygltf::Material& gm, const std::string& el, const char* name) {
    return {extension_object(gm.extensions, name), el + ".extensions." + name};
}

void clearcoat(const GltfContext& ctx, const Extension& x, TextureTable& t, MaterialDesc& d) {
    d.clearcoat = json_number(ctx, x.el, x.obj, "clearcoatFactor", 0.0f, kUnit);
    d.clearcoat_texture = t.json_ref(x.el, x.obj, "clearcoatTexture", ImageEncoding::Linear);
    d.clearcoat_roughness = json_number(ctx, x.el, x.obj, "clearcoatRoughnessFactor", 0.0f, kUnit);
    d.clearcoat_roughness_texture =
        t.json_ref(x.el, x.obj, "clearcoatRoughnessTexture", ImageEncoding::Linear);
    d.clearcoat_normal_texture = t.json_ref(x.el, x.obj, "clearcoatNormalTexture",
                                            ImageEncoding::Linear, &d.clearcoat_normal_scale);
}

void sheen(const GltfContext& ctx, const Extension& x, TextureTable& t, MaterialDesc& d) {
    d.sheen_color = json_vec3(ctx, x.el, x.obj, "sheenColorFactor", d.sheen_color, kUnit);
    d.sheen_color_texture = t.json_ref(x.el, x.obj, "sheenColorTexture", ImageEncoding::Srgb);
    d.sheen_roughness = json_number(ctx, x.el, x.obj, "sheenRoughnessFactor", 0.0f, kUnit);
    d.sheen_roughness_texture =
        t.json_ref(x.el, x.obj, "sheenRoughnessTexture", ImageEncoding::Linear);
}

// attenuationDistance: the schema's exclusiveMinimum 0; omitted is infinity (no
// absorption). attenuationColor is a linear transmittance colour, like a factor.
void volume(const GltfContext& ctx, const Extension& x, TextureTable& t, MaterialDesc& d) {
    d.thickness = json_number(ctx, x.el, x.obj, "thicknessFactor", 0.0f, kNonNegative);
    d.thickness_texture = t.json_ref(x.el, x.obj, "thicknessTexture", ImageEncoding::Linear);
    d.attenuation_distance =
        json_number(ctx, x.el, x.obj, "attenuationDistance", INFINITY, kPositive);
    d.attenuation_color =
        json_vec3(ctx, x.el, x.obj, "attenuationColor", d.attenuation_color, kUnit);
}

// The thickness range is used as given, also when the minimum exceeds the maximum (the
// spec does not forbid it; the texture then runs from thick to thin).
void iridescence(const GltfContext& ctx, const Extension& x, TextureTable& t, MaterialDesc& d) {
    d.iridescence = json_number(ctx, x.el, x.obj, "iridescenceFactor", 0.0f, kUnit);
    d.iridescence_texture = t.json_ref(x.el, x.obj, "iridescenceTexture", ImageEncoding::Linear);
    d.iridescence_ior = json_number(ctx, x.el, x.obj, "iridescenceIor", 1.3f, kAtLeastOne);
    d.iridescence_thickness_min =
        json_number(ctx, x.el, x.obj, "iridescenceThicknessMinimum", 100.0f, kNonNegative);
    d.iridescence_thickness_max =
        json_number(ctx, x.el, x.obj, "iridescenceThicknessMaximum", 400.0f, kNonNegative);
    d.iridescence_thickness_texture =
        t.json_ref(x.el, x.obj, "iridescenceThicknessTexture", ImageEncoding::Linear);
}

void anisotropy(const GltfContext& ctx, const Extension& x, TextureTable& t, MaterialDesc& d) {
    d.anisotropy_strength = json_number(ctx, x.el, x.obj, "anisotropyStrength", 0.0f, kUnit);
    d.anisotropy_rotation = json_number(ctx, x.el, x.obj, "anisotropyRotation", 0.0f);
    d.anisotropy_texture = t.json_ref(x.el, x.obj, "anisotropyTexture", ImageEncoding::Linear);
}

void diffuse_transmission(const GltfContext& ctx, const Extension& x, TextureTable& t,
                          MaterialDesc& d) {
    d.diffuse_transmission =
        json_number(ctx, x.el, x.obj, "diffuseTransmissionFactor", 0.0f, kUnit);
    d.diffuse_transmission_texture =
        t.json_ref(x.el, x.obj, "diffuseTransmissionTexture", ImageEncoding::Linear);
    d.diffuse_transmission_color = json_vec3(ctx, x.el, x.obj, "diffuseTransmissionColorFactor",
                                             d.diffuse_transmission_color, kUnit);
    d.diffuse_transmission_color_texture =
        t.json_ref(x.el, x.obj, "diffuseTransmissionColorTexture", ImageEncoding::Srgb);
}

}  // namespace

void load_material_extensions(const GltfContext& ctx, const tinygltf::Material& gm,
                              const std::string& el, TextureTable& textures, MaterialDesc& d) {
    clearcoat(ctx, find(gm, el, "KHR_materials_clearcoat"), textures, d);
    sheen(ctx, find(gm, el, "KHR_materials_sheen"), textures, d);
    volume(ctx, find(gm, el, "KHR_materials_volume"), textures, d);
    iridescence(ctx, find(gm, el, "KHR_materials_iridescence"), textures, d);
    anisotropy(ctx, find(gm, el, "KHR_materials_anisotropy"), textures, d);
    diffuse_transmission(ctx, find(gm, el, "KHR_materials_diffuse_transmission"), textures, d);
    // KHR_materials_dispersion: 20 / V_d (Abbe number); 0 is none.
    const Extension disp = find(gm, el, "KHR_materials_dispersion");
    d.dispersion = json_number(ctx, disp.el, disp.obj, "dispersion", 0.0f, kNonNegative);
}

}  // namespace penumbra
