// Image decoding: the sRGB transfer pair, decoding from memory and files, alpha left
// linear, and errors that name the image.
#include "io/image_reader.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "core/error.h"
#include "io/color.h"
#include "io/image_writer.h"
#include "support/gltf_builder.h"

namespace penumbra {
namespace {

using test::ScratchDir;

TEST(ImageReader, SrgbTransfer) {
    EXPECT_FLOAT_EQ(srgb_to_linear(0), 0.0f);
    EXPECT_FLOAT_EQ(srgb_to_linear(1), 1.0f);
    EXPECT_NEAR(srgb_to_linear(0.5f), 0.21404f, 1e-5f);
    EXPECT_NEAR(srgb_to_linear(0.04045f), 0.04045f / 12.92f, 1e-7f);  // linear segment
    for (float v = 0; v <= 1.0f; v += 0.01f)
        EXPECT_NEAR(linear_to_srgb(srgb_to_linear(v)), v, 1e-5f);
}

TEST(ImageReader, DecodesPngFromMemoryAndFile) {
    ScratchDir dir;
    Image img(3, 2, 3);
    for (size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = float(i) / 17.0f;
    write_preview(dir.file("a.png"), img);
    std::ifstream f(dir.file("a.png"), std::ios::binary);
    const std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(f),
                                     std::istreambuf_iterator<char>()};
    const Image lin = decode_image(bytes, "memory", ImageEncoding::Linear);
    ASSERT_EQ(lin.width, 3);
    ASSERT_EQ(lin.height, 2);
    ASSERT_EQ(lin.channels, 3);
    const Image srgb = read_image(dir.file("a.png"), ImageEncoding::Srgb);
    for (size_t i = 0; i < img.pixels.size(); ++i) {
        const float code = std::round(linear_to_srgb(img.pixels[i]) * 255.0f) / 255.0f;
        EXPECT_NEAR(lin.pixels[i], code, 1e-6f) << i;
        EXPECT_NEAR(srgb.pixels[i], srgb_to_linear(code), 1e-6f) << i;
    }
}

TEST(ImageReader, AlphaStaysLinear) {
    ScratchDir dir;
    Image img(1, 1, 4);
    img.pixels = {0.5f, 0.5f, 0.5f, 0.5f};
    write_exr(dir.file("a.exr"), img);
    const Image r = read_image(dir.file("a.exr"), ImageEncoding::Srgb);
    ASSERT_EQ(r.channels, 4);
    EXPECT_NEAR(r.pixels[0], srgb_to_linear(0.5f), 1e-3f);
    EXPECT_NEAR(r.pixels[3], 0.5f, 1e-3f);
}

TEST(ImageReader, ErrorsNameTheImage) {
    try {
        decode_image({1, 2, 3, 4, 5, 6}, "scene.gltf: images[2]", ImageEncoding::Linear);
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_STREQ(e.what(), "scene.gltf: images[2]: cannot decode image: unrecognised format");
    }
    try {
        decode_image({0x89, 'P', 'N', 'G', 0, 0}, "bad", ImageEncoding::Linear);
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("bad: cannot decode image: ", 0), 0u) << e.what();
    }
    try {
        read_image("no/such/image.png", ImageEncoding::Srgb);
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_STREQ(e.what(), "no/such/image.png: cannot open file");
    }
}

}  // namespace
}  // namespace penumbra
