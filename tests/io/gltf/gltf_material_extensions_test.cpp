// Every property of the KHR material extensions (clearcoat, sheen, volume, iridescence,
// anisotropy, dispersion, diffuse transmission, specular), unlit and specular-glossiness:
// the specs' defaults, non-default values, each texture in its own slot with its UV set
// and encoding (sRGB or linear), colour conversion, and the texture source choice
// (EXT_texture_webp, KHR_texture_basisu). Range and type errors: gltf_material_ranges_test.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "io/color/color.h"
#include "io/gltf/gltf_loader.h"
#include "io/image/image_reader.h"
#include "support/gltf_builder.h"
#include "support/material_gltf.h"

namespace penumbra {
namespace {

using test::BufferStorage;
using test::GltfBuilder;
using test::kTexel;
using test::load_with_material;
using test::png_uri;
using test::ScratchDir;

void expect_texture(const Scene& s, const TextureRef& r, int k, ImageEncoding encoding,
                    const char* what) {
    SCOPED_TRACE(what);
    ASSERT_TRUE(r.valid());
    EXPECT_EQ(r.texcoord, k % 2);
    EXPECT_EQ(r.offset.x, float(k));
    const Image img = s.images.at(s.textures.at(size_t(r.texture)).image).to_image();
    ASSERT_EQ(img.channels, 4);
    const float code = kTexel[0] / 255.0f;
    const float red = encoding == ImageEncoding::Srgb ? srgb_to_linear(code) : code;
    EXPECT_NEAR(img.at(0, 0)[0], red, 1e-5f);
    EXPECT_NEAR(img.at(0, 0)[3], kTexel[3] / 255.0f, 1e-6f);  // alpha is never sRGB
}

void expect_eq(Vec3 a, Vec3 b) {
    EXPECT_FLOAT_EQ(a.x, b.x);
    EXPECT_FLOAT_EQ(a.y, b.y);
    EXPECT_FLOAT_EQ(a.z, b.z);
}

// The spec's default of every property the extensions add (written out, not taken from
// MaterialDesc's initialisers, so a wrong initialiser fails here).
void expect_spec_defaults(const MaterialDesc& m) {
    EXPECT_EQ(m.clearcoat, 0.0f);
    EXPECT_EQ(m.clearcoat_roughness, 0.0f);
    EXPECT_EQ(m.clearcoat_normal_scale, 1.0f);
    expect_eq(m.sheen_color, Vec3(0.0f));
    EXPECT_EQ(m.sheen_roughness, 0.0f);
    EXPECT_EQ(m.thickness, 0.0f);
    EXPECT_EQ(m.attenuation_distance, INFINITY);
    expect_eq(m.attenuation_color, Vec3(1.0f));
    EXPECT_EQ(m.iridescence, 0.0f);
    EXPECT_EQ(m.iridescence_ior, 1.3f);
    EXPECT_EQ(m.iridescence_thickness_min, 100.0f);
    EXPECT_EQ(m.iridescence_thickness_max, 400.0f);
    EXPECT_EQ(m.anisotropy_strength, 0.0f);
    EXPECT_EQ(m.anisotropy_rotation, 0.0f);
    EXPECT_EQ(m.dispersion, 0.0f);
    EXPECT_EQ(m.diffuse_transmission, 0.0f);
    expect_eq(m.diffuse_transmission_color, Vec3(1.0f));
    EXPECT_EQ(m.specular, 1.0f);
    expect_eq(m.specular_color, Vec3(1.0f));
    EXPECT_FALSE(m.unlit);
    EXPECT_FALSE(m.specular_glossiness);
    for (const TextureRef* r :
         {&m.clearcoat_texture, &m.clearcoat_roughness_texture, &m.clearcoat_normal_texture,
          &m.sheen_color_texture, &m.sheen_roughness_texture, &m.thickness_texture,
          &m.iridescence_texture, &m.iridescence_thickness_texture, &m.anisotropy_texture,
          &m.diffuse_transmission_texture, &m.diffuse_transmission_color_texture,
          &m.specular_texture, &m.specular_color_texture, &m.specular_glossiness_texture})
        EXPECT_FALSE(r->valid());
}

TEST(GltfMaterialExtensions, EmptyExtensionObjectsGiveTheSpecDefaults) {
    const Scene s = load_with_material(R"({}, {"extensions": {
        "KHR_materials_clearcoat": {}, "KHR_materials_sheen": {}, "KHR_materials_volume": {},
        "KHR_materials_iridescence": {}, "KHR_materials_anisotropy": {},
        "KHR_materials_dispersion": {}, "KHR_materials_diffuse_transmission": {},
        "KHR_materials_specular": {}}})");
    ASSERT_EQ(s.materials.size(), 2u);
    for (const MaterialDesc& m : s.materials) {
        SCOPED_TRACE(m.name);
        expect_spec_defaults(m);
    }
}

TEST(GltfMaterialExtensions, EveryPropertyAndTexture) {
    const Scene s = load_with_material(R"({"extensions": {
        "KHR_materials_clearcoat": {"clearcoatFactor": 0.7, "clearcoatTexture": @1,
            "clearcoatRoughnessFactor": 0.3,
            "clearcoatRoughnessTexture": @2,
            "clearcoatNormalTexture": {"index": 0, "texCoord": 1, "scale": 0.4,
                "extensions": {"KHR_texture_transform": {"offset": [3, 0]}}}},
        "KHR_materials_sheen": {"sheenColorFactor": [0.9, 0.5, 0.1],
            "sheenColorTexture": @4, "sheenRoughnessFactor": 0.6,
            "sheenRoughnessTexture": @5},
        "KHR_materials_volume": {"thicknessFactor": 2.5, "thicknessTexture": @6,
            "attenuationDistance": 0.25, "attenuationColor": [0.1, 0.5, 0.9]},
        "KHR_materials_iridescence": {"iridescenceFactor": 0.8,
            "iridescenceTexture": @7, "iridescenceIor": 1.8,
            "iridescenceThicknessMinimum": 250, "iridescenceThicknessMaximum": 1200,
            "iridescenceThicknessTexture": @8},
        "KHR_materials_anisotropy": {"anisotropyStrength": 0.45, "anisotropyRotation": -1.25,
            "anisotropyTexture": @9},
        "KHR_materials_dispersion": {"dispersion": 0.35},
        "KHR_materials_diffuse_transmission": {"diffuseTransmissionFactor": 0.55,
            "diffuseTransmissionTexture": @10,
            "diffuseTransmissionColorFactor": [0.2, 0.4, 0.8],
            "diffuseTransmissionColorTexture": @11},
        "KHR_materials_specular": {"specularFactor": 0.65, "specularTexture": @12,
            "specularColorFactor": [1.5, 0.5, 0.25],
            "specularColorTexture": @13}}})");
    const MaterialDesc& m = s.materials.at(0);
    const ImageEncoding lin = ImageEncoding::Linear, srgb = ImageEncoding::Srgb;
    EXPECT_FLOAT_EQ(m.clearcoat, 0.7f);
    expect_texture(s, m.clearcoat_texture, 1, lin, "clearcoatTexture");
    EXPECT_FLOAT_EQ(m.clearcoat_roughness, 0.3f);
    expect_texture(s, m.clearcoat_roughness_texture, 2, lin, "clearcoatRoughnessTexture");
    expect_texture(s, m.clearcoat_normal_texture, 3, lin, "clearcoatNormalTexture");
    EXPECT_FLOAT_EQ(m.clearcoat_normal_scale, 0.4f);
    expect_eq(m.sheen_color, {0.9f, 0.5f, 0.1f});
    expect_texture(s, m.sheen_color_texture, 4, srgb, "sheenColorTexture");
    EXPECT_FLOAT_EQ(m.sheen_roughness, 0.6f);
    expect_texture(s, m.sheen_roughness_texture, 5, lin, "sheenRoughnessTexture");
    EXPECT_FLOAT_EQ(m.thickness, 2.5f);
    expect_texture(s, m.thickness_texture, 6, lin, "thicknessTexture");
    EXPECT_FLOAT_EQ(m.attenuation_distance, 0.25f);
    expect_eq(m.attenuation_color, {0.1f, 0.5f, 0.9f});
    EXPECT_FLOAT_EQ(m.iridescence, 0.8f);
    expect_texture(s, m.iridescence_texture, 7, lin, "iridescenceTexture");
    EXPECT_FLOAT_EQ(m.iridescence_ior, 1.8f);
    EXPECT_FLOAT_EQ(m.iridescence_thickness_min, 250.0f);
    EXPECT_FLOAT_EQ(m.iridescence_thickness_max, 1200.0f);
    expect_texture(s, m.iridescence_thickness_texture, 8, lin, "iridescenceThicknessTexture");
    EXPECT_FLOAT_EQ(m.anisotropy_strength, 0.45f);
    EXPECT_FLOAT_EQ(m.anisotropy_rotation, -1.25f);
    expect_texture(s, m.anisotropy_texture, 9, lin, "anisotropyTexture");
    EXPECT_FLOAT_EQ(m.dispersion, 0.35f);
    EXPECT_FLOAT_EQ(m.diffuse_transmission, 0.55f);
    expect_texture(s, m.diffuse_transmission_texture, 10, lin, "diffuseTransmissionTexture");
    expect_eq(m.diffuse_transmission_color, {0.2f, 0.4f, 0.8f});
    expect_texture(s, m.diffuse_transmission_color_texture, 11, srgb,
                   "diffuseTransmissionColorTexture");
    EXPECT_FLOAT_EQ(m.specular, 0.65f);
    expect_texture(s, m.specular_texture, 12, lin, "specularTexture");
    expect_eq(m.specular_color, {1.5f, 0.5f, 0.25f});
    expect_texture(s, m.specular_color_texture, 13, srgb, "specularColorTexture");
    // One glTF texture, used as colour and as data: one Scene image per encoding.
    EXPECT_EQ(s.images.size(), 2u);
    EXPECT_FALSE(m.unlit);
    EXPECT_FALSE(m.specular_glossiness);
}

TEST(GltfMaterialExtensions, UnlitAndSpecularGlossiness) {
    const Scene s = load_with_material(R"({"extensions": {"KHR_materials_unlit": {}},
          "pbrMetallicRoughness": {"baseColorFactor": [1, 0.2, 0, 1]}},
        {"pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1], "metallicFactor": 1,
             "roughnessFactor": 0.1, "metallicRoughnessTexture": {"index": 0}},
         "extensions": {"KHR_materials_pbrSpecularGlossiness": {
             "diffuseFactor": [0.9, 0.8, 0.7, 0.6], "diffuseTexture": @1,
             "specularFactor": [0.3, 0.2, 0.1], "glossinessFactor": 0.75,
             "specularGlossinessTexture": @2}}},
        {"extensions": {"KHR_materials_pbrSpecularGlossiness": {}}})");
    const MaterialDesc& unlit = s.materials.at(0);
    EXPECT_TRUE(unlit.unlit);
    EXPECT_FLOAT_EQ(unlit.base_color.y, 0.2f);
    EXPECT_FALSE(unlit.specular_glossiness);

    const MaterialDesc& sg = s.materials.at(1);
    EXPECT_TRUE(sg.specular_glossiness);
    EXPECT_FALSE(sg.unlit);
    EXPECT_FLOAT_EQ(sg.base_color.x, 0.9f);
    EXPECT_FLOAT_EQ(sg.base_color.w, 0.6f);
    expect_texture(s, sg.base_color_texture, 1, ImageEncoding::Srgb, "diffuseTexture");
    expect_eq(sg.specular_color, {0.3f, 0.2f, 0.1f});
    EXPECT_FLOAT_EQ(sg.roughness, 0.25f);
    EXPECT_EQ(sg.metallic, 0.0f);
    // The metallic-roughness fallback for other viewers is dropped.
    EXPECT_FALSE(sg.metallic_roughness_texture.valid());
    expect_texture(s, sg.specular_glossiness_texture, 2, ImageEncoding::Srgb,
                   "specularGlossinessTexture");

    // The archived spec's defaults: diffuse 1, specular 1, glossiness 1 (roughness 0).
    const MaterialDesc& d = s.materials.at(2);
    EXPECT_TRUE(d.specular_glossiness);
    EXPECT_EQ(d.base_color.x, 1.0f);
    EXPECT_EQ(d.base_color.w, 1.0f);
    expect_eq(d.specular_color, Vec3(1.0f));
    EXPECT_EQ(d.roughness, 0.0f);
    EXPECT_EQ(d.metallic, 0.0f);
    EXPECT_FALSE(d.base_color_texture.valid());
}

// The new colour factors and sRGB textures go into the working space; data textures and
// factors do not.
TEST(GltfMaterialExtensions, ColoursConvertToTheWorkingSpace) {
    const Mat3 m = Mat3::from_columns({0.5f, 0.1f, 0}, {0.25f, 0.8f, 0}, {0, 0.1f, 1});
    const std::string material = R"({"extensions": {
        "KHR_materials_sheen": {"sheenColorFactor": [0.9, 0.5, 0.1],
            "sheenColorTexture": @0, "sheenRoughnessTexture": @1},
        "KHR_materials_volume": {"attenuationColor": [0.1, 0.5, 0.9]},
        "KHR_materials_diffuse_transmission": {"diffuseTransmissionColorFactor": [0.2, 0.4, 0.8]},
        "KHR_materials_clearcoat": {"clearcoatFactor": 0.5}}})";
    const Scene a = load_with_material(material), b = load_with_material(material, m);
    const MaterialDesc &ma = a.materials.at(0), &mb = b.materials.at(0);
    expect_eq(mb.sheen_color, m * ma.sheen_color);
    expect_eq(mb.attenuation_color, m * ma.attenuation_color);
    expect_eq(mb.diffuse_transmission_color, m * ma.diffuse_transmission_color);
    EXPECT_EQ(mb.clearcoat, 0.5f);
    auto texel = [](const Scene& s, const TextureRef& r) {
        // Through the lookup, at texel 0's centre: it applies the working-space matrix.
        const Texture& tex = s.textures.at(size_t(r.texture));
        const TextureImage& img = s.images.at(tex.image);
        return lookup(tex, img, {0.5f / img.width(), 0.5f / img.height()});
    };
    const Vec4 ca = texel(a, ma.sheen_color_texture), cb = texel(b, mb.sheen_color_texture);
    const Vec3 want = m * Vec3(ca.x, ca.y, ca.z);
    EXPECT_NEAR(cb.x, want.x, 1e-6f);
    EXPECT_NEAR(cb.y, want.y, 1e-6f);
    EXPECT_NEAR(cb.z, want.z, 1e-6f);
    EXPECT_EQ(cb.w, ca.w);
    const Vec4 da = texel(a, ma.sheen_roughness_texture), db = texel(b, mb.sheen_roughness_texture);
    EXPECT_EQ(db.x, da.x);
    EXPECT_EQ(db.y, da.y);
}

// EXT_texture_webp and KHR_texture_basisu name the image to use; `source` is only the
// fallback. The test's images are PNGs: the decoder goes by the bytes' signature, not the
// MIME type (KTX2 decoding itself: tests/io/image/).
TEST(GltfMaterialExtensions, TextureSourcesWebpFirstThenSource) {
    ScratchDir dir;
    GltfBuilder b;
    b.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3");
    const unsigned char other[4] = {255, 0, 0, 255};
    const std::string images = R"("images": [{"uri": ")" + png_uri(dir, other) +
                               R"("}, {"uri": ")" + png_uri(dir) +
                               R"(", "mimeType": "image/webp"}],)";
    auto load = [&](const std::string& texture) {
        const std::string members =
            R"("extensionsUsed": ["EXT_texture_webp", "KHR_texture_basisu"],)" + images +
            R"("textures": [)" + texture + R"(],
            "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],)" +
            test::one_mesh_scene(R"({"attributes": {"POSITION": 0}})");
        const Scene s = load_gltf(b.write(dir, "src.gltf", members, BufferStorage::DataUri));
        EXPECT_EQ(s.images.size(), 1u);  // only the chosen image is decoded
        return s.images.at(0).texel(0, 0, 0).x;
    };
    const float webp = srgb_to_linear(kTexel[0] / 255.0f);
    EXPECT_NEAR(load(R"({"source": 0, "extensions": {"EXT_texture_webp": {"source": 1}}})"), webp,
                1e-5f);
    EXPECT_NEAR(load(R"({"extensions": {"EXT_texture_webp": {"source": 1}}})"), webp, 1e-5f);
    EXPECT_EQ(load(R"({"source": 0})"), 1.0f);
    EXPECT_NEAR(load(R"({"source": 0, "extensions": {"KHR_texture_basisu": {"source": 1}}})"),
                webp, 1e-5f);
    const std::pair<const char*, const char*> errors[] = {
        {R"({"source": 0, "extensions": {"EXT_texture_webp": {"source": 2}}})",
         "textures[0].extensions.EXT_texture_webp: source index 2 out of range (2 images)"},
        {R"({"source": 0, "extensions": {"EXT_texture_webp": {}}})",
         "textures[0].extensions.EXT_texture_webp: source must be an integer image index"},
        {R"({"extensions": {"KHR_texture_basisu": {"source": 2}}})",
         "textures[0].extensions.KHR_texture_basisu: source index 2 out of range (2 images)"},
    };
    for (const auto& [texture, message] : errors) {
        try {
            load(texture);
            ADD_FAILURE() << texture;
        } catch (const SceneError& e) {
            EXPECT_EQ(std::string(e.what()), dir.file("src.gltf") + ": " + message);
        }
    }
}

}  // namespace
}  // namespace penumbra
