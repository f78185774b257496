// glTF materials to MaterialDesc: the core metallic-roughness model, the extensions that
// change its factors (emissive strength, IOR, specular, transmission), unlit and the
// archived specular-glossiness model; the lobe extensions are in
// gltf_material_extensions.cpp. Colour textures (base colour, emissive, specular colour,
// specular-glossiness) are sRGB-encoded and decoded to linear; data textures are linear.
// Every texture reference may carry KHR_texture_transform.
#include <exception>

#include "io/gltf/material/gltf_material_extensions.h"
#include "io/gltf/material/gltf_material_json.h"
#include "io/gltf/material/gltf_material_textures.h"
#include "io/gltf/animation/gltf_property_animation.h"

namespace penumbra {

namespace {

Vec3 vec3(const GltfContext& ctx, const std::string& el, const char* key,
          const std::vector<double>& v) {
    if (v.size() != 3) ctx.fail(el, std::string(key) + " must have 3 numbers");
    return {float(v[0]), float(v[1]), float(v[2])};
}

// KHR_materials_specular: specularFactor scales the dielectric F0 (texture A),
// specularColorFactor tints it (texture RGB, sRGB); the colour may exceed 1 (the spec
// allows it: f0 is clamped after the IOR's value is applied).
void load_specular(const GltfContext& ctx, const tinygltf::Material& gm, const std::string& el,
                   TextureTable& textures, MaterialDesc& d) {
    const tinygltf::Value& spec = extension_object(gm.extensions, "KHR_materials_specular");
    const std::string sel = el + ".extensions.KHR_materials_specular";
    d.specular = json_number(ctx, sel, spec, "specularFactor", 1.0f, kUnit);
    d.specular_texture = textures.json_ref(sel, spec, "specularTexture", ImageEncoding::Linear);
    d.specular_color =
        json_vec3(ctx, sel, spec, "specularColorFactor", d.specular_color, kNonNegative);
    d.specular_color_texture =
        textures.json_ref(sel, spec, "specularColorTexture", ImageEncoding::Srgb);
}

// KHR_materials_pbrSpecularGlossiness (archived; Khronos glTF
// extensions/2.0/Archived/KHR_materials_pbrSpecularGlossiness): replaces
// pbrMetallicRoughness, which the file keeps only as a fallback for other viewers. Its
// textures are sRGB: diffuse RGBA (alpha linear), specular RGB with glossiness in A
// (linear: the sRGB transfer never touches alpha).
void load_specular_glossiness(const GltfContext& ctx, const tinygltf::Material& gm,
                              const std::string& el, TextureTable& textures, MaterialDesc& d) {
    const tinygltf::Value& sg =
        extension_object(gm.extensions, "KHR_materials_pbrSpecularGlossiness");
    if (!sg.IsObject()) return;
    const std::string gel = el + ".extensions.KHR_materials_pbrSpecularGlossiness";
    d.specular_glossiness = true;
    float diffuse[4] = {1, 1, 1, 1};
    json_numbers(ctx, gel, sg, "diffuseFactor", 4, diffuse, kUnit);
    d.base_color = {diffuse[0], diffuse[1], diffuse[2], diffuse[3]};
    d.base_color_texture = textures.json_ref(gel, sg, "diffuseTexture", ImageEncoding::Srgb);
    d.specular_color = json_vec3(ctx, gel, sg, "specularFactor", Vec3(1.0f), kUnit);
    d.roughness = 1 - json_number(ctx, gel, sg, "glossinessFactor", 1.0f, kUnit);
    d.specular_glossiness_texture =
        textures.json_ref(gel, sg, "specularGlossinessTexture", ImageEncoding::Srgb);
    d.metallic = 0;
    d.metallic_roughness_texture = {};
}

// Material i of the file, read from `gm`: the file's own, or a copy with animated values.
MaterialDesc load_material(const GltfContext& ctx, const tinygltf::Material& gm, size_t i,
                           TextureTable& textures) {
    const std::string el = element("materials", i);
    MaterialDesc d;
    d.name = gm.name.empty() ? el : gm.name;

    const tinygltf::PbrMetallicRoughness& pbr = gm.pbrMetallicRoughness;
    const std::string pel = el + ".pbrMetallicRoughness";
    if (pbr.baseColorFactor.size() != 4) ctx.fail(pel, "baseColorFactor must have 4 numbers");
    for (int c = 0; c < 4; ++c) d.base_color[c] = float(pbr.baseColorFactor[size_t(c)]);
    d.base_color_texture = textures.ref(pel + ".baseColorTexture", pbr.baseColorTexture.index,
                                        pbr.baseColorTexture.texCoord, ImageEncoding::Srgb,
                                        pbr.baseColorTexture.extensions);
    d.metallic = float(pbr.metallicFactor);
    d.roughness = float(pbr.roughnessFactor);
    d.metallic_roughness_texture =
        textures.ref(pel + ".metallicRoughnessTexture", pbr.metallicRoughnessTexture.index,
                     pbr.metallicRoughnessTexture.texCoord, ImageEncoding::Linear,
                     pbr.metallicRoughnessTexture.extensions);

    d.normal_texture =
        textures.ref(el + ".normalTexture", gm.normalTexture.index, gm.normalTexture.texCoord,
                     ImageEncoding::Linear, gm.normalTexture.extensions);
    d.normal_scale = float(gm.normalTexture.scale);
    d.occlusion_texture = textures.ref(el + ".occlusionTexture", gm.occlusionTexture.index,
                                       gm.occlusionTexture.texCoord, ImageEncoding::Linear,
                                       gm.occlusionTexture.extensions);
    d.occlusion_strength = float(gm.occlusionTexture.strength);
    // tinygltf leaves emissiveFactor empty when the file omits it (default black).
    if (!gm.emissiveFactor.empty()) d.emissive = vec3(ctx, el, "emissiveFactor", gm.emissiveFactor);
    d.emissive_texture =
        textures.ref(el + ".emissiveTexture", gm.emissiveTexture.index, gm.emissiveTexture.texCoord,
                     ImageEncoding::Srgb, gm.emissiveTexture.extensions);

    if (gm.alphaMode == "OPAQUE")
        d.alpha_mode = AlphaMode::Opaque;
    else if (gm.alphaMode == "MASK")
        d.alpha_mode = AlphaMode::Mask;
    else if (gm.alphaMode == "BLEND")
        d.alpha_mode = AlphaMode::Blend;
    else
        ctx.fail(el, "alphaMode '" + gm.alphaMode + "' is not OPAQUE, MASK or BLEND");
    d.alpha_cutoff = float(gm.alphaCutoff);
    d.double_sided = gm.doubleSided;

    const std::string xel = el + ".extensions.";
    const tinygltf::Value& strength =
        extension_object(gm.extensions, "KHR_materials_emissive_strength");
    d.emissive_strength = json_number(ctx, xel + "KHR_materials_emissive_strength", strength,
                                      "emissiveStrength", 1.0f, kNonNegative);
    d.ior = json_number(ctx, xel + "KHR_materials_ior",
                        extension_object(gm.extensions, "KHR_materials_ior"), "ior", 1.5f);
    load_specular(ctx, gm, el, textures, d);

    const tinygltf::Value& tr = extension_object(gm.extensions, "KHR_materials_transmission");
    const std::string tel = xel + "KHR_materials_transmission";
    d.transmission = json_number(ctx, tel, tr, "transmissionFactor", 0.0f, kUnit);
    d.transmission_texture =
        textures.json_ref(tel, tr, "transmissionTexture", ImageEncoding::Linear);

    // KHR_materials_unlit has no properties: its presence is the whole statement.
    d.unlit = extension_object(gm.extensions, "KHR_materials_unlit").IsObject();
    load_specular_glossiness(ctx, gm, el, textures, d);
    load_material_extensions(ctx, gm, el, textures, d);
    return d;
}


// KHR_animation_pointer: material i as animated at shutter open and, where it changes
// within the shutter, kPropertySteps copies across it, appended to the scene's materials
// (Scene::material_steps).
void load_animated_material(const GltfContext& ctx, size_t i, const GltfAnimations& animations,
                            const Shutter& shutter, TextureTable& textures, Scene& scene) {
    const tinygltf::Material& gm = ctx.model.materials[i];
    const std::vector<PropertyChannel> channels = usable_channels(
        ctx, element("materials", i), gm, animations.properties(PointerObject::Material, int(i)));
    scene.materials[i] = load_material(ctx, animated(gm, channels, shutter.open), i, textures);
    if (!changes_within(channels, shutter)) return;
    scene.material_steps.resize(ctx.model.materials.size());
    for (int k = 0; k < kPropertySteps; ++k) {
        scene.material_steps[i].push_back(int(scene.materials.size()));
        scene.materials.push_back(load_material(
            ctx, animated(gm, channels, shutter.time(k, kPropertySteps)), i, textures));
    }
    scene.timed_materials = true;
}

}  // namespace

void load_materials(const GltfContext& ctx, const std::function<const GltfAnimations&()>& animations,
                    const Shutter& shutter, Scene& scene) {
    // Decoding texture images is most of a textured scene's load time, so they decode in
    // parallel: a silent dry run over the materials (into a scratch scene) lists them in
    // use order, then the real pass takes them. An error stops the dry run; the real pass
    // reports it where a serial load would.
    ImagePrefetch prefetch;
    {
        GltfContext dry = ctx;
        dry.silent = true;
        Scene scratch;
        TextureTable collect(dry, scratch, &prefetch);
        try {
            for (size_t i = 0; i < ctx.model.materials.size(); ++i)
                load_material(dry, ctx.model.materials[i], i, collect);
        } catch (const std::exception&) {
        }
    }
    prefetch.decode_all();
    TextureTable textures(ctx, scene, &prefetch);
    for (size_t i = 0; i < ctx.model.materials.size(); ++i)
        scene.materials.push_back(load_material(ctx, ctx.model.materials[i], i, textures));
    const GltfAnimations& animated = animations();
    for (size_t i = 0; i < ctx.model.materials.size(); ++i)
        if (!animated.properties(PointerObject::Material, int(i)).empty())
            load_animated_material(ctx, i, animated, shutter, textures, scene);
}

}  // namespace penumbra
