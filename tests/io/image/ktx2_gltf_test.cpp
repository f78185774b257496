// KHR_texture_basisu end to end: glTFast's TextureVariants-Embedded-KTX.gltf (the extension
// required, a UASTC + Zstandard KTX2 image in a bufferView, no PNG fallback) loads with its
// one image decoded once, its 3 mip levels from the file, used by both textures; a KTX2
// image in a data: URI (which tinygltf does not decode) loads without warnings.
#include <gtest/gtest.h>

#include <fstream>

#include "io/gltf/gltf_loader.h"
#include "support/gltf_builder.h"
#include "support/paths.h"
#include "tests/io/image/ktx2_test_files.h"

namespace penumbra {
namespace {

TEST(Ktx2Gltf, TextureVariantsEmbeddedKtxLoads) {
    const Scene s = load_gltf(test::shared_path("scenes/ktx2/TextureVariants-Embedded-KTX.gltf"));
    ASSERT_EQ(s.images.size(), 1u);
    const TextureImage& img = s.images[0];
    EXPECT_EQ(img.width(), 4);
    EXPECT_EQ(img.height(), 4);
    EXPECT_EQ(img.levels(), 3);
    EXPECT_EQ(img.channels(), 3);
    EXPECT_TRUE(img.srgb());
    ASSERT_EQ(s.materials.size(), 2u);
    for (const auto& m : s.materials) {
        ASSERT_TRUE(m.base_color_texture.valid());
        EXPECT_EQ(s.textures.at(size_t(m.base_color_texture.texture)).image, 0u);
    }
}

// The same texture as an external file next to the glTF, the extension optional (used).
TEST(Ktx2Gltf, ExternalFileImageLoads) {
    test::ScratchDir dir;
    const std::vector<uint8_t> ktx2 = test::read_ktx2("luminance_alpha_reference_basis");
    std::ofstream(dir.file("la.ktx2"), std::ios::binary)
        .write(reinterpret_cast<const char*>(ktx2.data()), std::streamsize(ktx2.size()));
    test::GltfBuilder b;
    b.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3");
    const std::string members =
        R"("extensionsUsed": ["KHR_texture_basisu"],
        "images": [{"uri": "la.ktx2", "mimeType": "image/ktx2"}],
        "textures": [{"extensions": {"KHR_texture_basisu": {"source": 0}}}],
        "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],)" +
        test::one_mesh_scene(R"({"attributes": {"POSITION": 0}, "material": 0})");
    const Scene s = load_gltf(b.write(dir, "file.gltf", members, test::BufferStorage::DataUri));
    ASSERT_EQ(s.images.size(), 1u);
    EXPECT_EQ(s.images[0].width(), 32);
    EXPECT_EQ(s.images[0].channels(), 4);
    EXPECT_FALSE(s.images[0].srgb());  // the file's DFD says linear
}

TEST(Ktx2Gltf, DataUriImageLoadsWithoutWarnings) {
    test::ScratchDir dir;
    test::GltfBuilder b;
    b.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3");
    const std::string members =
        R"("extensionsUsed": ["KHR_texture_basisu"], "extensionsRequired": ["KHR_texture_basisu"],
        "images": [{"uri": "data:image/ktx2;base64,)" +
        test::base64(test::read_ktx2("cyan_rgb_reference_uastc")) +
        R"("}], "textures": [{"extensions": {"KHR_texture_basisu": {"source": 0}}}],
        "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],)" +
        test::one_mesh_scene(R"({"attributes": {"POSITION": 0}, "material": 0})");
    testing::internal::CaptureStderr();
    const Scene s = load_gltf(b.write(dir, "uri.gltf", members, test::BufferStorage::DataUri));
    const std::string log = testing::internal::GetCapturedStderr();
    EXPECT_EQ(log, "");
    ASSERT_EQ(s.images.size(), 1u);
    EXPECT_EQ(s.images[0].width(), 64);
    EXPECT_EQ(s.images[0].code(0, 10, 10, 1), 255u);
    EXPECT_TRUE(s.materials.at(0).base_color_texture.valid());
}

}  // namespace
}  // namespace penumbra
