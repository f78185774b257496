#include "io/gltf/material/gltf_material_textures.h"

#include "io/gltf/gltf_accessor.h"
#include "io/gltf/material/gltf_material_json.h"
#include "io/image/data_uri.h"
#include "io/image/image_reader.h"

namespace penumbra {

namespace {

// The KHR_texture_transform object of a textureInfo's extensions, or a null Value.
const tinygltf::Value& texture_transform(const tinygltf::ExtensionMap& extensions) {
    static const tinygltf::Value none;
    const auto it = extensions.find("KHR_texture_transform");
    return it == extensions.end() ? none : it->second;
}

}  // namespace

TextureTable::TextureTable(const GltfContext& ctx, Scene& scene, ImagePrefetch* prefetch)
    : m_ctx(ctx), m_scene(scene), m_prefetch(prefetch) {
    for (const std::string& name : ctx.model.extensionsUsed) {
        if (name == "EXT_texture_webp") m_allow_webp = true;
        if (name == "KHR_texture_basisu") m_allow_ktx2 = true;
    }
    for (const std::string& name : ctx.model.extensionsRequired)
        if (name == "KHR_texture_basisu") m_ktx2_required = true;
    // An image gets a pyramid unless every texture using it samples without mipmaps
    // (minFilter NEAREST or LINEAR); indices are checked where they are used.
    for (const tinygltf::Texture& gt : ctx.model.textures) {
        const bool valid_sampler =
            gt.sampler >= 0 && size_t(gt.sampler) < ctx.model.samplers.size();
        const int min_filter =
            valid_sampler ? ctx.model.samplers[size_t(gt.sampler)].minFilter : -1;
        if (min_filter == TINYGLTF_TEXTURE_FILTER_NEAREST ||
            min_filter == TINYGLTF_TEXTURE_FILTER_LINEAR)
            continue;
        m_mipmapped.insert(gt.source);
        for (const char* ext : {"EXT_texture_webp", "KHR_texture_basisu"}) {
            const tinygltf::Value& v = extension_object(gt.extensions, ext);
            if (v.IsObject() && v.Has("source") && v.Get("source").IsInt())
                m_mipmapped.insert(v.Get("source").GetNumberAsInt());
        }
    }
}

// glTF's minFilter (texture filter and mipmap filter in one enum); absent (-1) or
// unknown: trilinear, the implementation's choice the spec allows.
void TextureTable::set_min_filter(int filter, Texture& tex) {
    switch (filter) {
        case TINYGLTF_TEXTURE_FILTER_NEAREST:
            tex.min_nearest = true;
            tex.mip = MipFilter::None;
            break;
        case TINYGLTF_TEXTURE_FILTER_LINEAR:
            tex.mip = MipFilter::None;
            break;
        case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST:
            tex.min_nearest = true;
            tex.mip = MipFilter::Nearest;
            break;
        case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST:
            tex.mip = MipFilter::Nearest;
            break;
        case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR:
            tex.min_nearest = true;
            break;
        default:
            break;
    }
}

TextureRef TextureTable::ref(const std::string& el, int texture, int texcoord,
                             ImageEncoding encoding, const tinygltf::ExtensionMap& extensions) {
    TextureRef r;
    if (texture == -1) return r;  // tinygltf's "absent"
    m_ctx.check_index(el, "texture", texture, m_ctx.model.textures.size(), "textures");
    const tinygltf::Value& xf = texture_transform(extensions);
    if (xf.IsObject()) {
        const std::string xel = el + ".extensions.KHR_texture_transform";
        r.offset = json_vec2(m_ctx, xel, xf, "offset", r.offset);
        r.rotation = json_number(m_ctx, xel, xf, "rotation", r.rotation);
        r.scale = json_vec2(m_ctx, xel, xf, "scale", r.scale);
        if (xf.Has("texCoord")) {
            if (!xf.Get("texCoord").IsInt()) m_ctx.fail(xel, "texCoord is not an integer");
            texcoord = xf.Get("texCoord").GetNumberAsInt();
        }
    }
    if (texcoord < 0) m_ctx.fail(el, "texCoord " + std::to_string(texcoord) + " is negative");
    // TriangleMesh keeps TEXCOORD_0 and _1 only.
    if (texcoord > 1) {
        m_ctx.warn(el,
                   "TEXCOORD_" + std::to_string(texcoord) + " is not supported; using TEXCOORD_0");
        texcoord = 0;
    }
    r.texture = texture_index(texture, encoding);
    r.texcoord = texcoord;
    return r;
}

TextureRef TextureTable::json_ref(const std::string& el, const tinygltf::Value& obj,
                                  const char* key, ImageEncoding encoding, float* scale) {
    if (!obj.Has(key)) return {};
    const std::string tel = el + "." + key;
    const tinygltf::Value& info = obj.Get(key);
    if (!info.IsObject() || !info.Has("index") || !info.Get("index").IsInt())
        m_ctx.fail(tel, "must be a textureInfo with an integer index");
    int texcoord = 0;
    if (info.Has("texCoord")) {
        if (!info.Get("texCoord").IsInt()) m_ctx.fail(tel, "texCoord is not an integer");
        texcoord = info.Get("texCoord").GetNumberAsInt();
    }
    if (scale) *scale = json_number(m_ctx, tel, info, "scale", 1.0f);
    tinygltf::ExtensionMap extensions;
    if (info.Has("extensions") && info.Get("extensions").Has("KHR_texture_transform"))
        extensions["KHR_texture_transform"] = info.Get("extensions").Get("KHR_texture_transform");
    const int index = info.Get("index").GetNumberAsInt();
    // ref() takes -1 as tinygltf's "absent"; written in the file, it is a bad index.
    if (index < 0)
        m_ctx.check_index(tel, "texture", index, m_ctx.model.textures.size(), "textures");
    return ref(tel, index, texcoord, encoding, extensions);
}

int TextureTable::texture_index(int index, ImageEncoding encoding) {
    const auto key = std::make_pair(index, int(encoding));
    if (auto it = m_textures.find(key); it != m_textures.end()) return it->second;
    const tinygltf::Texture& gt = m_ctx.model.textures[size_t(index)];
    const std::string el = element("textures", size_t(index));
    Texture tex;
    if (gt.sampler != -1) {
        m_ctx.check_index(el, "sampler", gt.sampler, m_ctx.model.samplers.size(), "samplers");
        const tinygltf::Sampler& s = m_ctx.model.samplers[size_t(gt.sampler)];
        const std::string sel = element("samplers", size_t(gt.sampler));
        tex.wrap_s = wrap_mode(sel, "wrapS", s.wrapS);
        tex.wrap_t = wrap_mode(sel, "wrapT", s.wrapT);
        tex.nearest = s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST;
        set_min_filter(s.minFilter, tex);
    }
    const int ktx2 = basisu_source(gt, el);
    const int image = ktx2 >= 0 ? basisu_image(gt, el, ktx2, encoding)
                                : image_index(image_source(gt, el), encoding);
    if (image < 0) {  // undecodable: the texture is absent
        m_textures.emplace(key, -1);
        return -1;
    }
    tex.image = uint32_t(image);
    const int result = int(m_scene.textures.size());
    m_scene.textures.push_back(tex);
    m_textures.emplace(key, result);
    return result;
}

// KHR_texture_basisu: the KTX2 image a texture names (io/image/ktx2_decoder.h), or -1.
int TextureTable::basisu_source(const tinygltf::Texture& gt, const std::string& el) const {
    const tinygltf::Value& ext = extension_object(gt.extensions, "KHR_texture_basisu");
    if (!ext.IsObject()) return -1;
    const std::string kel = el + ".extensions.KHR_texture_basisu";
    if (!ext.Has("source") || !ext.Get("source").IsInt())
        m_ctx.fail(kel, "source must be an integer image index");
    const int source = ext.Get("source").GetNumberAsInt();
    m_ctx.check_index(kel, "source", source, m_ctx.model.images.size(), "images");
    return source;
}

// A KTX2 image that cannot be decoded is an error naming it where the extension is
// required or the texture has no other source; otherwise one warning, and the core
// `source` (PNG or JPEG) that the extension asks files to provide is used instead.
int TextureTable::basisu_image(const tinygltf::Texture& gt, const std::string& el, int ktx2,
                               ImageEncoding encoding) {
    std::string why;
    const int image = image_index(ktx2, encoding, &why);
    if (image >= 0 || why.empty()) return image;
    const tinygltf::Image& gi = m_ctx.model.images[size_t(ktx2)];
    const bool external = !gi.uri.empty() && gi.uri.compare(0, 5, "data:") != 0;
    const std::string label = external ? gi.uri : gi.name;
    const std::string iel =
        element("images", size_t(ktx2)) + (label.empty() ? "" : " ('" + label + "')");
    if (m_ktx2_required || gt.source == -1)
        m_ctx.fail(iel, "cannot decode KTX2 image: " + why +
                            (m_ktx2_required ? " (KHR_texture_basisu is required)"
                                             : " (no fallback source)"));
    if (m_ktx2_warned.insert(ktx2).second)
        m_ctx.warn(iel, "cannot decode KTX2 image: " + why + "; using the fallback source images[" +
                            std::to_string(gt.source) + "]");
    return image_index(image_source(gt, el), encoding);
}

// EXT_texture_webp: the WebP image when the texture names one (OIIO decodes WebP); the
// core `source` is then only the fallback for viewers without WebP. Textures with a
// KHR_texture_basisu (KTX2) image come here only for their fallback.
int TextureTable::image_source(const tinygltf::Texture& gt, const std::string& el) const {
    const tinygltf::Value& webp = extension_object(gt.extensions, "EXT_texture_webp");
    if (webp.IsObject()) {
        const std::string wel = el + ".extensions.EXT_texture_webp";
        if (!webp.Has("source") || !webp.Get("source").IsInt())
            m_ctx.fail(wel, "source must be an integer image index");
        const int source = webp.Get("source").GetNumberAsInt();
        m_ctx.check_index(wel, "source", source, m_ctx.model.images.size(), "images");
        return source;
    }
    if (gt.source == -1) m_ctx.fail(el, "has no source image");
    m_ctx.check_index(el, "source", gt.source, m_ctx.model.images.size(), "images");
    return gt.source;
}

int TextureTable::image_index(int index, ImageEncoding encoding, std::string* error) {
    const auto key = std::make_pair(index, int(encoding));
    if (auto it = m_images.find(key); it != m_images.end()) return it->second;
    if (auto it = m_undecodable.find(index); it != m_undecodable.end()) {
        if (error) *error = it->second;
        return -1;
    }
    const tinygltf::Image& gi = m_ctx.model.images[size_t(index)];
    const std::string el = element("images", size_t(index));
    const bool external = !gi.uri.empty() && gi.uri.compare(0, 5, "data:") != 0;
    std::vector<uint8_t> view;
    const std::vector<uint8_t>* bytes = &gi.image;  // captured undecoded by the image callback
    if (gi.bufferView >= 0)
        bytes = &(view = buffer_view_bytes(m_ctx, el, gi.bufferView));
    else if (gi.image.empty() && external)
        m_ctx.fail(el, "cannot read image file '" + gi.uri + "'");
    else if (gi.image.empty() && gi.uri.empty())
        m_ctx.fail(el, "has no image data");
    else if (gi.image.empty() && !decode_data_uri(gi.uri, &view))  // a MIME type tinygltf skips
        m_ctx.fail(el, "data: URI is not base64 data");
    else if (gi.image.empty())
        bytes = &view;
    const std::string label = external ? gi.uri : gi.name;
    const std::string named = label.empty() ? el : el + " ('" + label + "')";
    TextureDecodeLimits limits;
    limits.allow_webp = m_allow_webp;
    limits.allow_ktx2 = m_allow_ktx2;
    limits.max_pixels = m_ctx.max_texture_pixels;
    TextureImage img;
    try {
        const bool mipmapped = m_mipmapped.count(index) > 0;
        if (m_prefetch && m_prefetch->collecting()) {
            m_prefetch->record(key, *bytes, m_ctx.file + ": " + named, encoding, limits,
                               mipmapped);
            return 0;  // a dry run's placeholder
        }
        if (!m_prefetch || !m_prefetch->take(key, &img))
            img = decode_texture_image(*bytes, m_ctx.file + ": " + named, encoding, limits,
                                       mipmapped);
    } catch (const ImageDecodeError& e) {
        // Renderable without it: the textures using it are left out, so their materials
        // use their factors alone; one warning per image, whichever encodings use it.
        m_undecodable[index] = e.why();
        if (error) {
            *error = e.why();
            return -1;
        }
        m_ctx.warn(named,
                   "cannot decode image: " + e.why() + "; the textures using it are ignored");
        return -1;
    }
    img.name = external ? gi.uri : (gi.name.empty() ? el : gi.name);
    const int result = int(m_scene.images.size());
    m_scene.images.push_back(std::move(img));
    m_images.emplace(key, result);
    return result;
}

WrapMode TextureTable::wrap_mode(const std::string& el, const char* what, int mode) const {
    switch (mode) {
        case TINYGLTF_TEXTURE_WRAP_REPEAT:
            return WrapMode::Repeat;
        case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE:
            return WrapMode::ClampToEdge;
        case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT:
            return WrapMode::MirroredRepeat;
        default:
            m_ctx.fail(el,
                       std::string(what) + " " + std::to_string(mode) + " is not a glTF wrap mode");
    }
}

}  // namespace penumbra
