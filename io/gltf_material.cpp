// glTF materials to MaterialDesc, and the textures and images they reference. Colour
// textures (base colour, emissive) are sRGB-encoded and decoded to linear; data textures
// (metallic-roughness, normal, occlusion, transmission) are linear. An image used both
// ways is decoded twice, so each Scene image has one encoding. Every texture reference
// may carry KHR_texture_transform.
#include <map>
#include <utility>

#include "io/gltf_accessor.h"
#include "io/gltf_context.h"
#include "io/image_reader.h"

namespace penumbra {

namespace {

// Reads an optional number from an extension object; throws when it is not a number.
float number(const GltfContext& ctx, const std::string& el, const tinygltf::Value& obj,
             const char* key, float fallback) {
    if (!obj.Has(key)) return fallback;
    const tinygltf::Value& v = obj.Get(key);
    if (!v.IsNumber()) ctx.fail(el, std::string(key) + " is not a number");
    return float(v.GetNumberAsDouble());
}

// An optional array of two numbers.
Vec2 vec2(const GltfContext& ctx, const std::string& el, const tinygltf::Value& obj,
          const char* key, Vec2 fallback) {
    if (!obj.Has(key)) return fallback;
    const tinygltf::Value& v = obj.Get(key);
    if (!v.IsArray() || v.ArrayLen() != 2 || !v.Get(0).IsNumber() || !v.Get(1).IsNumber())
        ctx.fail(el, std::string(key) + " must have 2 numbers");
    return {float(v.Get(0).GetNumberAsDouble()), float(v.Get(1).GetNumberAsDouble())};
}

// The KHR_texture_transform object of a textureInfo's extensions, or a null Value.
const tinygltf::Value& texture_transform(const tinygltf::ExtensionMap& extensions) {
    static const tinygltf::Value none;
    const auto it = extensions.find("KHR_texture_transform");
    return it == extensions.end() ? none : it->second;
}

// Scene textures and images, created on first use by a material, keyed by the glTF
// index and the encoding the use implies.
class TextureTable {
public:
    TextureTable(const GltfContext& ctx, Scene& scene) : m_ctx(ctx), m_scene(scene) {}

    // The reference for a glTF textureInfo at element path `el`, with the extensions of
    // that textureInfo (for KHR_texture_transform).
    TextureRef ref(const std::string& el, int texture, int texcoord, ImageEncoding encoding,
                   const tinygltf::ExtensionMap& extensions) {
        TextureRef r;
        if (texture == -1) return r;  // tinygltf's "absent"
        m_ctx.check_index(el, "texture", texture, m_ctx.model.textures.size(), "textures");
        const tinygltf::Value& xf = texture_transform(extensions);
        if (xf.IsObject()) {
            const std::string xel = el + ".extensions.KHR_texture_transform";
            r.offset = vec2(m_ctx, xel, xf, "offset", r.offset);
            r.rotation = number(m_ctx, xel, xf, "rotation", r.rotation);
            r.scale = vec2(m_ctx, xel, xf, "scale", r.scale);
            if (xf.Has("texCoord")) {
                if (!xf.Get("texCoord").IsInt()) m_ctx.fail(xel, "texCoord is not an integer");
                texcoord = xf.Get("texCoord").GetNumberAsInt();
            }
        }
        if (texcoord < 0) m_ctx.fail(el, "texCoord " + std::to_string(texcoord) + " is negative");
        // TriangleMesh keeps TEXCOORD_0 and _1 only.
        if (texcoord > 1) {
            m_ctx.warn(
                el, "TEXCOORD_" + std::to_string(texcoord) + " is not supported; using TEXCOORD_0");
            texcoord = 0;
        }
        r.texture = texture_index(texture, encoding);
        r.texcoord = texcoord;
        return r;
    }

private:
    int texture_index(int index, ImageEncoding encoding) {
        const auto key = std::make_pair(index, int(encoding));
        if (auto it = m_textures.find(key); it != m_textures.end()) return it->second;
        const tinygltf::Texture& gt = m_ctx.model.textures[size_t(index)];
        const std::string el = element("textures", size_t(index));
        if (gt.source == -1) m_ctx.fail(el, "has no source image");
        m_ctx.check_index(el, "source", gt.source, m_ctx.model.images.size(), "images");
        Texture tex;
        if (gt.sampler != -1) {
            m_ctx.check_index(el, "sampler", gt.sampler, m_ctx.model.samplers.size(), "samplers");
            const tinygltf::Sampler& s = m_ctx.model.samplers[size_t(gt.sampler)];
            const std::string sel = element("samplers", size_t(gt.sampler));
            tex.wrap_s = wrap_mode(sel, "wrapS", s.wrapS);
            tex.wrap_t = wrap_mode(sel, "wrapT", s.wrapT);
            tex.nearest = s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST;
        }
        tex.image = uint32_t(image_index(gt.source, encoding));
        const int result = int(m_scene.textures.size());
        m_scene.textures.push_back(tex);
        m_textures.emplace(key, result);
        return result;
    }

    int image_index(int index, ImageEncoding encoding) {
        const auto key = std::make_pair(index, int(encoding));
        if (auto it = m_images.find(key); it != m_images.end()) return it->second;
        const tinygltf::Image& gi = m_ctx.model.images[size_t(index)];
        const std::string el = element("images", size_t(index));
        const bool external = !gi.uri.empty() && gi.uri.compare(0, 5, "data:") != 0;
        std::vector<uint8_t> bytes;
        if (gi.bufferView >= 0)
            bytes = buffer_view_bytes(m_ctx, el, gi.bufferView);
        else if (!gi.image.empty())
            bytes = gi.image;  // captured undecoded by the loader's image callback
        else if (external)
            m_ctx.fail(el, "cannot read image file '" + gi.uri + "'");
        else
            m_ctx.fail(el, "has no image data");
        Image img = decode_image(bytes, m_ctx.file + ": " + el, encoding);
        img.name = external ? gi.uri : (gi.name.empty() ? el : gi.name);
        const int result = int(m_scene.images.size());
        m_scene.images.push_back(std::move(img));
        m_images.emplace(key, result);
        return result;
    }

    WrapMode wrap_mode(const std::string& el, const char* what, int mode) const {
        switch (mode) {
            case TINYGLTF_TEXTURE_WRAP_REPEAT:
                return WrapMode::Repeat;
            case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE:
                return WrapMode::ClampToEdge;
            case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT:
                return WrapMode::MirroredRepeat;
            default:
                m_ctx.fail(el, std::string(what) + " " + std::to_string(mode) +
                                   " is not a glTF wrap mode");
        }
    }

    const GltfContext& m_ctx;
    Scene& m_scene;
    std::map<std::pair<int, int>, int> m_textures, m_images;
};

Vec3 vec3(const GltfContext& ctx, const std::string& el, const char* key,
          const std::vector<double>& v) {
    if (v.size() != 3) ctx.fail(el, std::string(key) + " must have 3 numbers");
    return {float(v[0]), float(v[1]), float(v[2])};
}

// The extension object `name` of a material, or a null Value when absent.
const tinygltf::Value& extension(const tinygltf::Material& gm, const char* name) {
    static const tinygltf::Value none;
    const auto it = gm.extensions.find(name);
    return it == gm.extensions.end() ? none : it->second;
}

// A textureInfo inside an extension object (tinygltf leaves those as JSON values).
TextureRef extension_texture(const GltfContext& ctx, const std::string& el,
                             const tinygltf::Value& obj, const char* key, TextureTable& textures) {
    if (!obj.Has(key)) return {};
    const tinygltf::Value& info = obj.Get(key);
    if (!info.IsObject() || !info.Has("index") || !info.Get("index").IsInt())
        ctx.fail(el, "must be a textureInfo with an integer index");
    int texcoord = 0;
    if (info.Has("texCoord")) {
        if (!info.Get("texCoord").IsInt()) ctx.fail(el, "texCoord is not an integer");
        texcoord = info.Get("texCoord").GetNumberAsInt();
    }
    tinygltf::ExtensionMap extensions;
    if (info.Has("extensions") && info.Get("extensions").Has("KHR_texture_transform"))
        extensions["KHR_texture_transform"] =
            info.Get("extensions").Get("KHR_texture_transform");
    return textures.ref(el, info.Get("index").GetNumberAsInt(), texcoord, ImageEncoding::Linear,
                        extensions);
}

MaterialDesc load_material(const GltfContext& ctx, size_t i, TextureTable& textures) {
    const tinygltf::Material& gm = ctx.model.materials[i];
    const std::string el = element("materials", i);
    MaterialDesc d;
    d.name = gm.name.empty() ? el : gm.name;

    const tinygltf::PbrMetallicRoughness& pbr = gm.pbrMetallicRoughness;
    const std::string pel = el + ".pbrMetallicRoughness";
    if (pbr.baseColorFactor.size() != 4) ctx.fail(pel, "baseColorFactor must have 4 numbers");
    for (int c = 0; c < 4; ++c) d.base_color[c] = float(pbr.baseColorFactor[size_t(c)]);
    d.base_color_texture =
        textures.ref(pel + ".baseColorTexture", pbr.baseColorTexture.index,
                     pbr.baseColorTexture.texCoord, ImageEncoding::Srgb,
                     pbr.baseColorTexture.extensions);
    d.metallic = float(pbr.metallicFactor);
    d.roughness = float(pbr.roughnessFactor);
    d.metallic_roughness_texture =
        textures.ref(pel + ".metallicRoughnessTexture", pbr.metallicRoughnessTexture.index,
                     pbr.metallicRoughnessTexture.texCoord, ImageEncoding::Linear,
                     pbr.metallicRoughnessTexture.extensions);

    d.normal_texture = textures.ref(el + ".normalTexture", gm.normalTexture.index,
                                    gm.normalTexture.texCoord, ImageEncoding::Linear,
                                    gm.normalTexture.extensions);
    d.normal_scale = float(gm.normalTexture.scale);
    d.occlusion_texture = textures.ref(el + ".occlusionTexture", gm.occlusionTexture.index,
                                       gm.occlusionTexture.texCoord, ImageEncoding::Linear,
                                       gm.occlusionTexture.extensions);
    d.occlusion_strength = float(gm.occlusionTexture.strength);
    // tinygltf leaves emissiveFactor empty when the file omits it (default black).
    if (!gm.emissiveFactor.empty()) d.emissive = vec3(ctx, el, "emissiveFactor", gm.emissiveFactor);
    d.emissive_texture = textures.ref(el + ".emissiveTexture", gm.emissiveTexture.index,
                                      gm.emissiveTexture.texCoord, ImageEncoding::Srgb,
                                      gm.emissiveTexture.extensions);

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
    const tinygltf::Value& strength = extension(gm, "KHR_materials_emissive_strength");
    d.emissive_strength =
        number(ctx, xel + "KHR_materials_emissive_strength", strength, "emissiveStrength", 1.0f);
    d.ior = number(ctx, xel + "KHR_materials_ior", extension(gm, "KHR_materials_ior"), "ior", 1.5f);
    const tinygltf::Value& spec = extension(gm, "KHR_materials_specular");
    const std::string sel = xel + "KHR_materials_specular";
    d.specular = number(ctx, sel, spec, "specularFactor", 1.0f);
    if (spec.Has("specularColorFactor")) {
        const tinygltf::Value& c = spec.Get("specularColorFactor");
        if (!c.IsArray() || c.ArrayLen() != 3)
            ctx.fail(sel, "specularColorFactor must have 3 numbers");
        for (int k = 0; k < 3; ++k) {
            if (!c.Get(k).IsNumber()) ctx.fail(sel, "specularColorFactor must have 3 numbers");
            d.specular_color[k] = float(c.Get(k).GetNumberAsDouble());
        }
    }
    // MaterialDesc has no slots for the specular textures; the factors still apply.
    if (spec.Has("specularTexture") || spec.Has("specularColorTexture"))
        ctx.warn_once("materials", "KHR_materials_specular textures are ignored");

    const tinygltf::Value& tr = extension(gm, "KHR_materials_transmission");
    const std::string tel = xel + "KHR_materials_transmission";
    d.transmission = number(ctx, tel, tr, "transmissionFactor", 0.0f);
    if (!(d.transmission >= 0 && d.transmission <= 1))
        ctx.fail(tel, "transmissionFactor must be in [0, 1]");
    d.transmission_texture = extension_texture(ctx, tel + ".transmissionTexture", tr,
                                               "transmissionTexture", textures);
    return d;
}

}  // namespace

void load_materials(const GltfContext& ctx, Scene& scene) {
    TextureTable textures(ctx, scene);
    for (size_t i = 0; i < ctx.model.materials.size(); ++i)
        scene.materials.push_back(load_material(ctx, i, textures));
}

}  // namespace penumbra
