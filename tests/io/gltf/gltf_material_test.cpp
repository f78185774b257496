// glTF materials, textures and images: factors and extensions, sRGB versus linear
// decoding (one image used both ways becomes two), image sources (data URI, bufferView
// in a GLB, external file) and sampler modes.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>

#include "io/gltf/gltf_loader.h"
#include "io/color/color.h"
#include "io/image/image_reader.h"
#include "io/image/image_writer.h"
#include "support/gltf_builder.h"

namespace penumbra {
namespace {

using test::BufferStorage;
using test::GltfBuilder;
using test::ScratchDir;

// A 2x1 RGB PNG; returns its bytes. The 8-bit values are round(255 * srgb(v)).
std::vector<uint8_t> write_png(const ScratchDir& dir, const std::string& name) {
    Image img(2, 1, 3);
    const float v[6] = {0.2140f, 0.5f, 1.0f, 0.0f, 0.05f, 0.8f};
    std::copy(v, v + 6, img.pixels.begin());
    write_preview(dir.file(name), img);
    std::ifstream f(dir.file(name), std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

float quantized(float linear) { return std::round(linear_to_srgb(linear) * 255.0f) / 255.0f; }

std::string quad_primitive(int material) {
    return R"({"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "material": )" +
           std::to_string(material) + "}";
}

void add_quad(GltfBuilder& b) {
    b.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3");
    b.add(std::vector<float>{0, 0, 1, 0, 0, 1}, test::kFloat, "VEC2");
}

TEST(GltfMaterial, SrgbAndLinearDecodingOfOneImage) {
    ScratchDir dir;
    const std::vector<uint8_t> png = write_png(dir, "tex.png");
    GltfBuilder b;
    add_quad(b);
    const std::string members = R"(
      "images": [{"uri": "data:image/png;base64,)" +
                                test::base64(png) + R"("}],
      "samplers": [{"magFilter": 9728, "wrapS": 33071, "wrapT": 33648}],
      "textures": [{"source": 0, "sampler": 0}],
      "materials": [{"pbrMetallicRoughness": {
          "baseColorTexture": {"index": 0, "texCoord": 1},
          "metallicRoughnessTexture": {"index": 0}}}],)" +
                                test::one_mesh_scene(quad_primitive(0));
    const Scene s = load_gltf(b.write(dir, "tex.gltf", members, BufferStorage::DataUri));
    ASSERT_EQ(s.images.size(), 2u);
    ASSERT_EQ(s.textures.size(), 2u);
    const MaterialDesc& m = s.materials[0];
    EXPECT_EQ(m.base_color_texture.texcoord, 1);
    const Texture& srgb = s.textures[size_t(m.base_color_texture.texture)];
    const Texture& lin = s.textures[size_t(m.metallic_roughness_texture.texture)];
    EXPECT_NE(srgb.image, lin.image);
    EXPECT_TRUE(srgb.nearest);
    EXPECT_EQ(srgb.wrap_s, WrapMode::ClampToEdge);
    EXPECT_EQ(srgb.wrap_t, WrapMode::MirroredRepeat);
    const Image a = s.images[srgb.image].to_image();
    const Image l = s.images[lin.image].to_image();
    ASSERT_EQ(a.width, 2);
    ASSERT_EQ(a.channels, 3);
    // sRGB: back to (about) the linear values written; linear: the stored 8-bit code.
    EXPECT_NEAR(a.at(0, 0)[0], 0.2140f, 5e-3f);
    EXPECT_NEAR(a.at(0, 0)[0], srgb_to_linear(quantized(0.2140f)), 1e-6f);
    EXPECT_NEAR(a.at(0, 0)[1], 0.5f, 5e-3f);
    EXPECT_FLOAT_EQ(a.at(0, 0)[2], 1.0f);
    EXPECT_NEAR(a.at(1, 0)[2], srgb_to_linear(quantized(0.8f)), 1e-6f);
    EXPECT_NEAR(l.at(0, 0)[0], quantized(0.2140f), 1e-6f);
    EXPECT_NEAR(l.at(1, 0)[1], quantized(0.05f), 1e-6f);
}

// The PNG from a bufferView inside a GLB, and from an external file beside a .gltf.
TEST(GltfMaterial, ImageFromBufferViewAndFile) {
    ScratchDir dir;
    const std::vector<uint8_t> png = write_png(dir, "beside.png");
    for (const BufferStorage storage : {BufferStorage::Glb, BufferStorage::DataUri}) {
        GltfBuilder b;
        add_quad(b);
        b.add(png, test::kUByte, "SCALAR");  // makes bufferView 2 (its accessor is unused)
        const std::string image = storage == BufferStorage::Glb
                                      ? R"({"bufferView": 2, "mimeType": "image/png"})"
                                      : R"({"uri": "beside.png"})";
        const std::string members = R"("images": [)" + image + R"(],
          "textures": [{"source": 0}],
          "materials": [{"emissiveTexture": {"index": 0}, "emissiveFactor": [1, 1, 1]}],)" +
                                    test::one_mesh_scene(quad_primitive(0));
        const std::string name = storage == BufferStorage::Glb ? "img.glb" : "img.gltf";
        const Scene s = load_gltf(b.write(dir, name, members, storage));
        ASSERT_EQ(s.images.size(), 1u) << name;
        // Emissive textures are sRGB.
        EXPECT_NEAR(s.images[0].texel(0, 0, 0).x, srgb_to_linear(quantized(0.2140f)), 1e-6f) << name;
        EXPECT_TRUE(s.materials[0].emissive_texture.valid());
    }
}

// glTF minFilter to the lookup's filters; an image gets a pyramid unless every sampler
// that uses it has a minFilter without mipmaps (NEAREST, LINEAR).
TEST(GltfMaterial, MinFiltersAndMipmaps) {
    ScratchDir dir;
    const std::vector<uint8_t> png = write_png(dir, "tex.png");
    const std::string uri = R"({"uri": "data:image/png;base64,)" + test::base64(png) + R"("})";
    struct Case {
        int min_filter;  // -1: absent
        MipFilter mip;
        bool min_nearest;
    };
    for (const Case c : {Case{-1, MipFilter::Linear, false}, Case{9728, MipFilter::None, true},
                         Case{9729, MipFilter::None, false}, Case{9984, MipFilter::Nearest, true},
                         Case{9985, MipFilter::Nearest, false}, Case{9986, MipFilter::Linear, true},
                         Case{9987, MipFilter::Linear, false}}) {
        SCOPED_TRACE(c.min_filter);
        GltfBuilder b;
        add_quad(b);
        const std::string sampler =
            c.min_filter < 0 ? "{}" : R"({"minFilter": )" + std::to_string(c.min_filter) + "}";
        const std::string members = R"("images": [)" + uri + R"(], "samplers": [)" + sampler +
                                    R"(], "textures": [{"source": 0, "sampler": 0}],
          "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],)" +
                                    test::one_mesh_scene(quad_primitive(0));
        const Scene s = load_gltf(b.write(dir, "min.gltf", members, BufferStorage::DataUri));
        ASSERT_EQ(s.textures.size(), 1u);
        EXPECT_EQ(s.textures[0].mip, c.mip);
        EXPECT_EQ(s.textures[0].min_nearest, c.min_nearest);
        EXPECT_FALSE(s.textures[0].nearest);
        EXPECT_EQ(s.images[0].levels(), c.mip == MipFilter::None ? 1 : 2);  // 2x1, 1x1
        EXPECT_EQ(s.images[0].format(), TexelFormat::U8);
    }
}

TEST(GltfMaterial, FactorsAndExtensions) {
    ScratchDir dir;
    GltfBuilder b;
    add_quad(b);
    const std::string members = R"(
      "extensionsUsed": ["KHR_materials_emissive_strength", "KHR_materials_ior",
                         "KHR_materials_specular"],
      "materials": [{"name": "glass",
          "pbrMetallicRoughness": {"baseColorFactor": [0.1, 0.2, 0.3, 0.4],
                                   "metallicFactor": 0.25, "roughnessFactor": 0.75},
          "emissiveFactor": [1, 0.5, 0], "alphaMode": "MASK", "alphaCutoff": 0.3,
          "doubleSided": true,
          "extensions": {
            "KHR_materials_emissive_strength": {"emissiveStrength": 5},
            "KHR_materials_ior": {"ior": 1.33},
            "KHR_materials_specular": {"specularFactor": 0.5,
                                       "specularColorFactor": [1, 0.5, 0.25]}}},
        {"alphaMode": "BLEND"}],)" +
                                test::one_mesh_scene(quad_primitive(1));
    const Scene s = load_gltf(b.write(dir, "mat.gltf", members, BufferStorage::DataUri));
    ASSERT_EQ(s.materials.size(), 2u);
    const MaterialDesc& m = s.materials[0];
    EXPECT_EQ(m.name, "glass");
    EXPECT_FLOAT_EQ(m.base_color.y, 0.2f);
    EXPECT_FLOAT_EQ(m.base_color.w, 0.4f);
    EXPECT_FLOAT_EQ(m.metallic, 0.25f);
    EXPECT_FLOAT_EQ(m.roughness, 0.75f);
    EXPECT_FLOAT_EQ(m.emissive.y, 0.5f);
    EXPECT_FLOAT_EQ(m.emissive_strength, 5.0f);
    EXPECT_EQ(m.alpha_mode, AlphaMode::Mask);
    EXPECT_FLOAT_EQ(m.alpha_cutoff, 0.3f);
    EXPECT_TRUE(m.double_sided);
    EXPECT_FLOAT_EQ(m.ior, 1.33f);
    EXPECT_FLOAT_EQ(m.specular, 0.5f);
    EXPECT_FLOAT_EQ(m.specular_color.z, 0.25f);
    EXPECT_FALSE(m.base_color_texture.valid());
    const MaterialDesc& d = s.materials[1];
    EXPECT_EQ(d.name, "materials[1]");
    EXPECT_EQ(d.alpha_mode, AlphaMode::Blend);
    EXPECT_FLOAT_EQ(d.ior, 1.5f);
    EXPECT_TRUE(is_black(d.emissive));
    EXPECT_EQ(s.meshes[0].material, 1);
}

}  // namespace
}  // namespace penumbra
