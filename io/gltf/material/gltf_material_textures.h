// Internal to io/: the Scene textures and images that materials use, created on first
// use and keyed by the glTF texture index and the encoding the use implies (an image used
// as colour and as data is decoded twice, so each Scene image has one encoding).
#pragma once

#include <map>
#include <string>
#include <set>
#include <utility>

#include "io/gltf/gltf_context.h"
#include "io/gltf/gltf_image_prefetch.h"
#include "io/image/image_reader.h"

namespace penumbra {

class TextureTable {
public:
    // With `prefetch`, images are recorded there while it is collecting, and taken from
    // it once decoded (gltf_image_prefetch.h).
    TextureTable(const GltfContext& ctx, Scene& scene, ImagePrefetch* prefetch = nullptr);

    // The reference for a glTF textureInfo at element path `el`, with the extensions of
    // that textureInfo (for KHR_texture_transform). texture -1: none. A texture whose
    // image cannot be decoded gives one warning and an invalid (absent) reference.
    TextureRef ref(const std::string& el, int texture, int texcoord, ImageEncoding encoding,
                   const tinygltf::ExtensionMap& extensions);

    // A textureInfo that tinygltf leaves as JSON (inside a material extension): obj[key]
    // at element path `el` (`el.key` in messages). `scale`, when given, receives a
    // normalTextureInfo's scale (default 1).
    TextureRef json_ref(const std::string& el, const tinygltf::Value& obj, const char* key,
                        ImageEncoding encoding, float* scale = nullptr);

private:
    int texture_index(int index, ImageEncoding encoding);
    int image_source(const tinygltf::Texture& gt, const std::string& el) const;
    int basisu_source(const tinygltf::Texture& gt, const std::string& el) const;
    int basisu_image(const tinygltf::Texture& gt, const std::string& el, int ktx2,
                     ImageEncoding encoding);
    // The Scene image of glTF image `index`; -1 when it cannot be decoded, with one
    // warning, or with the reason in *error (no warning) when error is given.
    int image_index(int index, ImageEncoding encoding, std::string* error = nullptr);
    static void set_min_filter(int filter, Texture& tex);
    WrapMode wrap_mode(const std::string& el, const char* what, int mode) const;

    const GltfContext& m_ctx;
    Scene& m_scene;
    bool m_allow_webp = false;  // EXT_texture_webp is used: WebP images are glTF images
    bool m_allow_ktx2 = false;     // KHR_texture_basisu is used: KTX2 images are glTF images
    bool m_ktx2_required = false;  // ... and required: an undecodable one is an error
    std::map<std::pair<int, int>, int> m_textures, m_images;  // -1: undecodable
    std::map<int, std::string> m_undecodable;  // glTF image indices, and why
    std::set<int> m_ktx2_warned;               // KTX2 images replaced by their fallback
    ImagePrefetch* m_prefetch = nullptr;
    std::set<int> m_mipmapped;  // glTF images that a texture samples with mipmaps
};

}  // namespace penumbra
