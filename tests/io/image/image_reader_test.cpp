// Image decoding: the sRGB transfer pair, decoding from memory and files, alpha left
// linear, and errors that name the image.
#include "io/image/image_reader.h"

#include <gtest/gtest.h>
#include <OpenImageIO/imageio.h>

#include <fstream>
#include <iterator>

#include "core/error.h"
#include "core/texture.h"
#include "io/color/color.h"
#include "io/image/image_writer.h"
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

// A PNG of `type` (UINT8 or UINT16) holding `codes` (w x h x c), written by OIIO; its bytes.
template <class T>
std::vector<uint8_t> png_of(const ScratchDir& dir, int w, int h, int c, const std::vector<T>& codes,
                            OIIO::TypeDesc type) {
    const std::string path = dir.file("codes.png");
    auto out = OIIO::ImageOutput::create(path);
    OIIO::ImageSpec spec(w, h, c, type);
    spec.attribute("oiio:UnassociatedAlpha", 1);  // the codes as given, alpha straight
    EXPECT_TRUE(out && out->open(path, spec));
    EXPECT_TRUE(out->write_image(type, codes.data()));
    out->close();
    std::ifstream f(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

// 8-bit files stay 8-bit, their colour codes as written whatever the alpha (glTF alpha is
// straight: OIIO must not premultiply); their sRGB lookup through the table equals the float path
// (OCIO's decode at load) at texel centres, and bilinear lookups between
// them agree to float rounding, far inside one 8-bit step.
TEST(ImageReader, EightBitTexturesMatchTheFloatPath) {
    ScratchDir dir;
    std::vector<uint8_t> codes(16 * 16 * 4);
    for (int i = 0; i < 256; ++i) {
        codes[size_t(4 * i)] = uint8_t(i);
        codes[size_t(4 * i + 1)] = uint8_t(255 - i);
        codes[size_t(4 * i + 2)] = uint8_t((i * 7) % 256);
        codes[size_t(4 * i + 3)] = uint8_t((i * 3) % 256);
    }
    const std::vector<uint8_t> png = png_of(dir, 16, 16, 4, codes, OIIO::TypeDesc::UINT8);
    for (const ImageEncoding enc : {ImageEncoding::Srgb, ImageEncoding::Linear}) {
        const TextureImage t = decode_texture_image(png, "codes.png", enc, {});
        ASSERT_EQ(t.format(), TexelFormat::U8);
        ASSERT_EQ(t.channels(), 4);
        EXPECT_EQ(t.levels(), 5);
        const TextureImage old(decode_image(png, "codes.png", enc), false);
        const Texture tex;
        float worst_centre = 0, worst = 0;
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) {
                EXPECT_EQ(t.code(0, x, y, 0), uint32_t(y * 16 + x));
                const Vec2 centre((x + 0.5f) / 16, (y + 0.5f) / 16), off(centre.x + 0.013f, centre.y - 0.021f);
                for (int c = 0; c < 4; ++c) {
                    worst_centre = std::max(worst_centre, std::abs(lookup(tex, t, centre)[c] -
                                                                   lookup(tex, old, centre)[c]));
                    worst = std::max(worst, std::abs(lookup(tex, t, off)[c] - lookup(tex, old, off)[c]));
                }
            }
        // OCIO evaluates the curve in float, the table in double: a few float ULPs apart.
        EXPECT_LE(worst_centre, 2e-7f) << int(enc);
        EXPECT_LE(worst, 1e-6f) << int(enc);
    }
}

// 16-bit files stay 16-bit: every code kept, linear as code / 65535, sRGB through the
// 16-bit table.
TEST(ImageReader, SixteenBitTexturesKeepTheirCodes) {
    ScratchDir dir;
    std::vector<uint16_t> codes(64 * 2);
    for (size_t i = 0; i < codes.size(); ++i) codes[i] = uint16_t(20000 + i);  // neighbours
    const std::vector<uint8_t> png = png_of(dir, 64, 1, 2, codes, OIIO::TypeDesc::UINT16);
    const TextureImage lin = decode_texture_image(png, "a", ImageEncoding::Linear, {});
    const TextureImage srgb = decode_texture_image(png, "a", ImageEncoding::Srgb, {});
    ASSERT_EQ(lin.format(), TexelFormat::U16);
    ASSERT_EQ(lin.channels(), 2);
    for (int x = 0; x < 64; ++x) {
        EXPECT_EQ(lin.code(0, x, 0, 0), codes[size_t(2 * x)]);
        EXPECT_FLOAT_EQ(lin.texel(0, x, 0).x, float(codes[size_t(2 * x)]) / 65535);
        EXPECT_EQ(srgb.texel(0, x, 0).x, srgb16_to_linear(codes[size_t(2 * x)]));
        EXPECT_NEAR(srgb.texel(0, x, 0).x, srgb_to_linear(codes[size_t(2 * x)] / 65535.0f), 1e-6f);
        EXPECT_FLOAT_EQ(srgb.texel(0, x, 0).w, float(codes[size_t(2 * x + 1)]) / 65535);  // linear
    }
    EXPECT_NE(lin.texel(0, 0, 0).x, lin.texel(0, 1, 0).x);
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
