// Images that cannot be decoded: one warning naming the file, the image and why, the
// material keeps its factors, and --strict (GltfLoadOptions::strict) makes it an error;
// formats glTF does not allow, the pixel limit, and the fuzzer's GIF inside a .glb.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "core/error.h"
#include "io/gltf/gltf_loader.h"
#include "support/gltf_builder.h"
#include "support/material_gltf.h"
#include "support/paths.h"

namespace penumbra {
namespace {

using test::BufferStorage;
using test::GltfBuilder;
using test::ScratchDir;

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

// A w x h RGB PNG written by OIIO.
std::vector<uint8_t> png_bytes(const ScratchDir& dir, int w, int h) {
    const std::string path = dir.file("w.png");
    auto out = OIIO::ImageOutput::create(path);
    EXPECT_TRUE(out && out->open(path, OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::UINT8)));
    std::vector<uint8_t> px(size_t(w * h * 3));
    for (size_t i = 0; i < px.size(); ++i) px[i] = uint8_t(i * 37);
    out->write_image(OIIO::TypeDesc::UINT8, px.data());
    out->close();
    std::ifstream f(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

// One triangle; material 0 uses texture 0 (images[0], the file bad.png) as colour and as
// metallic-roughness data, material 1 uses texture 1 (a good PNG).
std::string write_scene(const ScratchDir& dir, const std::vector<uint8_t>& bad) {
    std::ofstream(dir.file("bad.png"), std::ios::binary)
        .write(reinterpret_cast<const char*>(bad.data()), std::streamsize(bad.size()));
    GltfBuilder b;
    b.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3");
    b.add(std::vector<float>{0, 0, 1, 0, 0, 1}, test::kFloat, "VEC2");
    const std::string members =
        R"("images": [{"uri": "bad.png"}, {"uri": ")" + test::png_uri(dir) + R"("}],
        "textures": [{"source": 0}, {"source": 1}],
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.25, 0.5, 0.75, 1],
                         "roughnessFactor": 0.3, "baseColorTexture": {"index": 0},
                         "metallicRoughnessTexture": {"index": 0}}},
                      {"pbrMetallicRoughness": {"baseColorTexture": {"index": 1}}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1},
                                    "material": 0},
                                   {"attributes": {"POSITION": 0, "TEXCOORD_0": 1},
                                    "material": 1}]}],
        "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}])";
    return b.write(dir, "bad-image.gltf", members, BufferStorage::DataUri);
}

// A PNG cut off in the middle of its image data: the header is fine, libpng fails later.
std::vector<uint8_t> corrupt_png(const ScratchDir& dir) {
    std::vector<uint8_t> png = png_bytes(dir, 16, 16);
    png.resize(png.size() / 2);
    return png;
}

TEST(GltfBadImages, CorruptPngIsOneWarningAndTheFactorsRemain) {
    ScratchDir dir;
    const std::string path = write_scene(dir, corrupt_png(dir));
    testing::internal::CaptureStderr();
    const Scene s = load_gltf(path);
    const std::string log = testing::internal::GetCapturedStderr();
    const std::string warning = path + ": images[0] ('bad.png'): cannot decode image: ";
    EXPECT_EQ(count(log, warning), 1u) << log;  // used twice, as colour and as data
    EXPECT_EQ(count(log, warning + "truncated PNG (its IDAT chunk runs past the end of the "
                                   "data); the textures using it are ignored\n"),
              1u)
        << log;
    EXPECT_EQ(count(log, "the textures using it are ignored"), 1u) << log;
    ASSERT_EQ(s.materials.size(), 2u);
    const MaterialDesc& m = s.materials[0];
    EXPECT_FALSE(m.base_color_texture.valid());
    EXPECT_FALSE(m.metallic_roughness_texture.valid());
    EXPECT_EQ(m.base_color.x, 0.25f);
    EXPECT_EQ(m.base_color.z, 0.75f);
    EXPECT_EQ(m.roughness, 0.3f);
    EXPECT_TRUE(s.materials[1].base_color_texture.valid());
    EXPECT_EQ(s.images.size(), 1u);  // the good one only
}

TEST(GltfBadImages, StrictMakesTheWarningAnError) {
    ScratchDir dir;
    const std::string path = write_scene(dir, corrupt_png(dir));
    GltfLoadOptions options;
    options.strict = true;
    try {
        load_gltf(path, options);
        ADD_FAILURE();
    } catch (const SceneError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind(path + ": images[0] ('bad.png'): cannot decode image: ", 0), 0u)
            << what;
        EXPECT_NE(what.find("[--strict]"), std::string::npos) << what;
    }
    // A file without warnings loads the same either way.
    const std::string good = write_scene(dir, png_bytes(dir, 2, 2));
    testing::internal::CaptureStderr();
    EXPECT_EQ(load_gltf(good, options).images.size(), 3u);  // images[0] as colour and data
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

// Formats OIIO reads but glTF does not allow, and WebP without EXT_texture_webp, are
// never handed to a decoder.
TEST(GltfBadImages, OnlyPngAndJpegWithoutWebpExtension) {
    const auto text = [](const std::string& s) { return std::vector<uint8_t>(s.begin(), s.end()); };
    const std::pair<const char*, std::vector<uint8_t>> cases[] = {
        {"gif", text("GIF89a\x01\x00\x01\x00\x80\x00\x00")},
        {"ktx2", text("\xABKTX 20\xBB\r\n\x1a\n")},
        {"html", text("<!DOCTYPE html><title>404</title>")},
        {"webp", text(std::string("RIFF\0\0\0\0WEBPVP8L\x05\0\0\0\x2f\0\0\0\0", 25))},
    };
    for (const auto& [what, bytes] : cases) {
        SCOPED_TRACE(what);
        ScratchDir dir;
        const std::string path = write_scene(dir, bytes);
        testing::internal::CaptureStderr();
        const Scene s = load_gltf(path);
        const std::string log = testing::internal::GetCapturedStderr();
        EXPECT_EQ(count(log, path + ": images[0] ('bad.png'): cannot decode image: not a PNG or "
                                    "JPEG image; the textures using it are ignored\n"),
                  1u)
            << log;
        EXPECT_FALSE(s.materials.at(0).base_color_texture.valid());
    }
}

// KHR_texture_basisu with corrupt KTX2 bytes (the identifier alone): where the extension
// is optional, one warning naming the image and the texture's `source` fallback; without
// a fallback, or where the extension is required, an error naming the image and why.
TEST(GltfBadImages, BasisuFallsBackOrFailsNamingTheImage) {
    ScratchDir dir;
    const std::string ktx2 = "\xABKTX 20\xBB\r\n\x1a\n";
    std::ofstream(dir.file("t.ktx2"), std::ios::binary) << ktx2;
    GltfBuilder b;
    b.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3");
    auto load = [&](const std::string& texture, bool required = false) {
        const std::string members =
            R"("extensionsUsed": ["KHR_texture_basisu"],)" +
            std::string(required ? R"("extensionsRequired": ["KHR_texture_basisu"],)" : "") +
            R"("images": [{"uri": ")" + test::png_uri(dir) +
            R"("}, {"uri": "t.ktx2", "mimeType": "image/ktx2"}], "textures": [)" + texture +
            R"(], "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}},
                             {"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],)" +
            test::one_mesh_scene(R"({"attributes": {"POSITION": 0}, "material": 0})");
        return load_gltf(b.write(dir, "basisu.gltf", members, BufferStorage::DataUri));
    };
    const std::string both =
        R"({"source": 0, "extensions": {"KHR_texture_basisu": {"source": 1}}})";
    testing::internal::CaptureStderr();
    const Scene s = load(both);
    const std::string log = testing::internal::GetCapturedStderr();
    EXPECT_EQ(s.images.size(), 1u);
    EXPECT_TRUE(s.materials.at(0).base_color_texture.valid());
    EXPECT_EQ(count(log, "basisu.gltf: images[1] ('t.ktx2'): cannot decode KTX2 image: "
                                "KTX2: truncated KTX2 header; using the fallback source "
                                "images[0]"),
              1u)
        << log;
    const std::pair<std::string, bool> failing[] = {
        {R"({"extensions": {"KHR_texture_basisu": {"source": 1}}})", false}, {both, true}};
    for (const auto& [texture, required] : failing) {
        try {
            load(texture, required);
            ADD_FAILURE() << texture;
        } catch (const SceneError& e) {
            EXPECT_EQ(std::string(e.what()),
                      dir.file("basisu.gltf") +
                          ": images[1] ('t.ktx2'): cannot decode KTX2 image: KTX2: truncated "
                          "KTX2 header" +
                          (required ? " (KHR_texture_basisu is required)"
                                    : " (no fallback source)"));
        }
    }
}

TEST(GltfBadImages, PixelLimitIsAWarningNamingTheLimit) {
    ScratchDir dir;
    const std::string path = write_scene(dir, png_bytes(dir, 3, 2));
    GltfLoadOptions options;
    options.max_texture_pixels = 6;
    EXPECT_TRUE(load_gltf(path, options).materials.at(0).base_color_texture.valid());
    options.max_texture_pixels = 5;
    testing::internal::CaptureStderr();
    const Scene s = load_gltf(path, options);
    const std::string log = testing::internal::GetCapturedStderr();
    EXPECT_NE(log.find(path + ": images[0] ('bad.png'): cannot decode image: 3x2 is more than "
                              "the limit of 5 pixels (--max-texture-pixels)"),
              std::string::npos)
        << log;
    EXPECT_FALSE(s.materials.at(0).base_color_texture.valid());
    EXPECT_TRUE(s.materials.at(1).base_color_texture.valid());  // 1x1
}

// A fuzzed file (../shared/scenes/fuzz-found/README.md): a broken GIF in a .glb's
// buffer that OIIO's GIF reader throws std::length_error on. It is refused by its
// bytes, with the file and image named. The mutation also broke an animation's key
// times, which is an error naming its element, after the image's warning.
TEST(GltfBadImages, FuzzFoundFilesLoadWithClearMessages) {
    const std::string path = test::shared_path("scenes/fuzz-found/gif-in-glb.glb");
    testing::internal::CaptureStderr();
    std::string error;
    try {
        load_gltf(path);
    } catch (const SceneError& e) {
        error = e.what();
    }
    const std::string log = testing::internal::GetCapturedStderr();
    EXPECT_EQ(count(log, path + ": images[0]"), 1u) << log;
    EXPECT_EQ(count(log, "cannot decode image: not a PNG or JPEG image"), 1u) << log;
    EXPECT_EQ(error, path +
                         ": animations[0].samplers[0]: input times are not strictly "
                         "increasing (key 1)");
    GltfLoadOptions options;
    options.strict = true;
    try {
        load_gltf(path, options);
        ADD_FAILURE();
    } catch (const SceneError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind(path + ": images[0]", 0), 0u) << what;
        EXPECT_NE(what.find("not a PNG or JPEG image"), std::string::npos) << what;
    }
}

}  // namespace
}  // namespace penumbra
