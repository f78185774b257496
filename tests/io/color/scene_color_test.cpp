// Loading into a working space other than Rec.709: every colour glTF gives (factors,
// colour textures, vertex colours, light colours) is converted, data is not, and the
// Rec.709 default changes nothing.
#include "io/color/scene_color.h"

#include <gtest/gtest.h>

#include "io/color/color.h"
#include "io/gltf/gltf_loader.h"
#include "io/image/image_writer.h"
#include "support/gltf_builder.h"

namespace penumbra {
namespace {

using test::BufferStorage;
using test::GltfBuilder;
using test::ScratchDir;

void expect_near(Vec3 a, Vec3 b, float eps) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

// One textured, vertex-coloured triangle (texture 0 is both base colour and normal map)
// and a red point light one unit above the origin.
std::string write_scene(const ScratchDir& dir) {
    Image tex(2, 1, 3);
    tex.pixels = {0.8f, 0.2f, 0.1f, 0.1f, 0.3f, 0.9f};
    write_preview(dir.file("tex.png"), tex);
    GltfBuilder b;
    b.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3");
    b.add(std::vector<float>{0, 0, 1, 0, 0, 1}, test::kFloat, "VEC2");
    b.add(std::vector<float>{1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 0.5f}, test::kFloat, "VEC4");
    const std::string members = R"(
      "images": [{"uri": "tex.png"}], "textures": [{"source": 0}],
      "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.4, 0.2, 0.5],
                                              "baseColorTexture": {"index": 0}},
                     "normalTexture": {"index": 0}, "emissiveFactor": [1, 0, 0]}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1,
                                                 "COLOR_0": 2}, "material": 0}]}],
      "extensionsUsed": ["KHR_lights_punctual"],
      "extensions": {"KHR_lights_punctual": {"lights": [
        {"type": "point", "color": [1, 0, 0], "intensity": 1366}]}},
      "nodes": [{"mesh": 0}, {"extensions": {"KHR_lights_punctual": {"light": 0}},
                              "translation": [0, 0, 1]}],
      "scenes": [{"nodes": [0, 1]}], "scene": 0)";
    return b.write(dir, "scene.gltf", members, BufferStorage::DataUri);
}

Spectrum light_at_origin(const Scene& s) {
    const std::optional<LightSample> ls =
        s.lights.at(0)->sample_Li({{0, 0, 0}, {0, 0, 1}}, {0.5f, 0.5f}, 0);
    return ls ? ls->Li : Spectrum(0);
}

TEST(SceneColor, AcescgLoadConvertsColoursButNotData) {
    ScratchDir dir;
    const std::string path = write_scene(dir);
    const Scene rec709 = load_gltf(path);
    ColorSettings cs;
    cs.config = "builtin";
    cs.working_space = "ACEScg";
    const ColorPipeline acescg(cs);
    GltfLoadOptions lo;
    lo.rec709_to_working = acescg.rec709_to_working();
    const Scene cg = load_gltf(path, lo);

    // OCIO's own conversion is the reference for every colour.
    auto ocio = [&](Vec3 c) {
        float v[3] = {c.x, c.y, c.z};
        acescg.convert(v, 1, "Linear Rec.709 (sRGB)", "ACEScg");
        return Vec3(v[0], v[1], v[2]);
    };
    const MaterialDesc &a = rec709.materials[0], &b = cg.materials[0];
    expect_near(b.base_color.xyz(), ocio(a.base_color.xyz()), 1e-5f);
    EXPECT_EQ(b.base_color.w, a.base_color.w);  // alpha is not a colour
    expect_near(b.emissive, ocio(a.emissive), 1e-5f);
    EXPECT_GT(std::abs(b.emissive.x - a.emissive.x), 0.3f);
    expect_near(cg.meshes[0].colors[1].xyz(), ocio(rec709.meshes[0].colors[1].xyz()), 1e-5f);
    EXPECT_EQ(cg.meshes[0].colors[2].w, 0.5f);
    expect_near(light_at_origin(cg), ocio(light_at_origin(rec709)), 1e-5f);

    // Colour textures keep their texels; the lookup (texel 0's centre) converts.
    const Texture& tex_a = rec709.textures[a.base_color_texture.texture];
    const Texture& tex_b = cg.textures[b.base_color_texture.texture];
    const TextureImage& colour_a = rec709.images[tex_a.image];
    const TextureImage& colour_b = cg.images[tex_b.image];
    ASSERT_EQ(colour_a.channels(), 3);
    const Vec2 centre(0.5f / colour_a.width(), 0.5f / colour_a.height());
    EXPECT_EQ(lookup(tex_a, colour_a, centre).xyz(), colour_a.texel(0, 0, 0).xyz());
    expect_near(lookup(tex_b, colour_b, centre).xyz(), ocio(colour_a.texel(0, 0, 0).xyz()), 1e-5f);
    // The normal map decodes the same file as data: identical in both, unconverted.
    const TextureImage& data_a = rec709.images[rec709.textures[a.normal_texture.texture].image];
    const TextureImage& data_b = cg.images[cg.textures[b.normal_texture.texture].image];
    EXPECT_EQ(data_a.to_image().pixels, data_b.to_image().pixels);
    EXPECT_FALSE(data_b.color_matrix());
}

TEST(SceneColor, Rec709WorkingSpaceChangesNothing) {
    ScratchDir dir;
    const std::string path = write_scene(dir);
    GltfLoadOptions lo;
    lo.rec709_to_working = ColorPipeline::builtin().rec709_to_working();
    const Scene a = load_gltf(path), b = load_gltf(path, lo);
    EXPECT_EQ(a.images[0].to_image().pixels, b.images[0].to_image().pixels);
    EXPECT_FALSE(b.images[0].color_matrix());
    EXPECT_EQ(a.materials[0].base_color.x, b.materials[0].base_color.x);
    EXPECT_EQ(light_at_origin(a), light_at_origin(b));
}

TEST(SceneColor, EnvironmentImagesConvertRgbOnly) {
    Image img(1, 1, 4);
    img.pixels = {1, 0, 0, 0.5f};
    Mat3 m;
    m.m = {{{0.5, 0.25, 0}, {0, 1, 0}, {0.125, 0, 1}}};
    convert_image_colors(img, m);
    EXPECT_FLOAT_EQ(img.pixels[0], 0.5f);
    EXPECT_FLOAT_EQ(img.pixels[1], 0.0f);
    EXPECT_FLOAT_EQ(img.pixels[2], 0.125f);
    EXPECT_FLOAT_EQ(img.pixels[3], 0.5f);
}

}  // namespace
}  // namespace penumbra
