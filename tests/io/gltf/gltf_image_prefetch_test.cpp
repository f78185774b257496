// Texture images decoded in parallel ahead of the materials (io/gltf/gltf_image_prefetch.*)
// end up as a serial load leaves them: Scene::images in the order the materials first use
// them, an image used as colour and as data decoded once per encoding, and an
// undecodable image one warning, at its place.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <thread>
#include <vector>

#include "io/gltf/gltf_loader.h"
#include "support/gltf_builder.h"
#include "support/paths.h"

namespace penumbra {
namespace {

using test::ScratchDir;

// dir/name: a w x 2 RGB PNG, written by OIIO.
void write_png(const ScratchDir& dir, const std::string& name, int w) {
    const std::string path = dir.file(name);
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out && out->open(path, OIIO::ImageSpec(w, 2, 3, OIIO::TypeDesc::UINT8)));
    std::vector<uint8_t> px(size_t(w) * 2 * 3);
    for (size_t i = 0; i < px.size(); ++i) px[i] = uint8_t(i * 37 + size_t(w));
    out->write_image(OIIO::TypeDesc::UINT8, px.data());
    out->close();
}

// Eight images img0..img7 of widths 1..8, img5 not an image; texture t shows image 7 - t;
// material m uses texture m as base colour, and material 2 uses texture 7 as
// metallic-roughness data too.
TEST(GltfImagePrefetch, ImagesWarningsAndOrderAreThoseOfASerialLoad) {
    const ScratchDir dir;
    std::string images, textures, materials;
    for (int i = 0; i < 8; ++i) {
        if (i == 5)
            dir.write("img5.png", "<!DOCTYPE html>");
        else
            write_png(dir, "img" + std::to_string(i) + ".png", i + 1);
        images += std::string(i ? "," : "") + "{\"uri\":\"img" + std::to_string(i) + ".png\"}";
        textures += std::string(i ? "," : "") + "{\"source\":" + std::to_string(7 - i) + "}";
        materials += std::string(i ? "," : "") + "{\"pbrMetallicRoughness\":{" +
                     "\"baseColorTexture\":{\"index\":" + std::to_string(i) + "}" +
                     (i == 2 ? ",\"metallicRoughnessTexture\":{\"index\":7}" : "") + "}}";
    }
    test::GltfBuilder b;
    b.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3");
    b.add(std::vector<float>{0, 0, 1, 0, 0, 1}, test::kFloat, "VEC2");
    const std::string path = b.write(
        dir, "eight.gltf",
        "\"images\":[" + images + "],\"textures\":[" + textures + "],\"materials\":[" + materials +
            "],\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"TEXCOORD_0\":1},"
            "\"material\":0}]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]",
        test::BufferStorage::DataUri);
    for (int run = 0; run < 2; ++run) {
        testing::internal::CaptureStderr();
        const Scene s = load_gltf(path);
        const std::string log = testing::internal::GetCapturedStderr();
        // Use order: materials 0..7 show images 7, 6, 5 (undecodable), 4, 3, 2, 1, 0, and
        // material 2's data texture is image 0 again, linear, between images 5 and 4.
        std::vector<std::string> names;
        std::vector<int> widths;
        for (const TextureImage& img : s.images) {
            names.push_back(img.name);
            widths.push_back(img.width());
        }
        EXPECT_EQ(names, (std::vector<std::string>{"img7.png", "img6.png", "img0.png", "img4.png",
                                                   "img3.png", "img2.png", "img1.png", "img0.png"}))
            << log;
        EXPECT_EQ(widths, (std::vector<int>{8, 7, 1, 5, 4, 3, 2, 1}));
        ASSERT_EQ(s.materials.size(), 8u);
        EXPECT_EQ(s.materials[2].base_color_texture.texture, -1);  // image 5
        EXPECT_GE(s.materials[2].metallic_roughness_texture.texture, 0);
        // Image 0 as data (linear) and as colour (sRGB): each decoded in its encoding.
        const Texture& data = s.textures[size_t(s.materials[2].metallic_roughness_texture.texture)];
        const Texture& colour = s.textures[size_t(s.materials[7].base_color_texture.texture)];
        EXPECT_EQ(data.image, 2u);
        EXPECT_EQ(colour.image, 7u);
        const Vec4 linear = lookup(data, s.images[2], {0.5f, 0.25f});
        const Vec4 srgb = lookup(colour, s.images[7], {0.5f, 0.25f});
        EXPECT_NEAR(linear.x, 1 / 255.0f, 1e-6f);  // the first byte, as written
        EXPECT_LT(srgb.x, linear.x);               // sRGB-decoded: darker
        EXPECT_EQ(log.find("warning: "), log.rfind("warning: ")) << log;  // just one
        EXPECT_NE(log.find(path + ": images[5] ('img5.png'): cannot decode image: "),
                  std::string::npos)
            << log;
    }
}

TEST(GltfImagePrefetch, JpegsWithIccProfilesOpenSafelyInParallel) {
    // chess-board.glb's JPEG textures carry ICC profiles, which OIIO 2.4 decodes through
    // state its threads share: opened at once they freed one block twice (the ASan pass
    // caught it in a load's parallel prefetch). Several loads at once, each decoding in
    // parallel, open many such headers together; all must load the same images.
    const std::string path = test::shared_path("scenes/wild/ChessBoard/chess-board.glb");
    const Scene reference = load_gltf(path);
    ASSERT_FALSE(reference.images.empty());
    std::vector<size_t> counts(3, 0);
    std::vector<std::thread> threads;
    for (size_t t = 0; t < counts.size(); ++t)
        threads.emplace_back([&, t] { counts[t] = load_gltf(path).images.size(); });
    for (std::thread& t : threads) t.join();
    for (size_t n : counts) EXPECT_EQ(n, reference.images.size());
}

}  // namespace
}  // namespace penumbra
