// The KTX2 decoder on Khronos' conformance files: sizes, channels, transfer functions,
// the file's own mip levels, the pixels the files are known to hold, and agreement of the
// ETC1S and UASTC encodings of the same pictures.
#include "io/image/ktx2_decoder.h"

#include <gtest/gtest.h>

#include <cmath>

#include "io/image/image_reader.h"
#include "tests/io/image/ktx2_test_files.h"

namespace penumbra {
namespace {

constexpr uint64_t kLimit = kDefaultMaxTexturePixels;

struct Expected {
    const char* name;
    int width, height, file_levels, channels;
    bool srgb;
};

// From the README's header table: every supported file.
constexpr Expected kFiles[] = {
    {"color_grid_basis", 1024, 1024, 1, 3, true},
    {"ktx_document_basis", 1024, 1024, 11, 4, true},
    {"rgba-mipmap-reference-basis", 64, 64, 7, 3, true},
    {"alpha_simple_basis", 8, 8, 1, 4, true},
    {"luminance_alpha_reference_basis", 32, 32, 1, 4, false},
    {"cyan_rgb_reference_uastc", 64, 64, 1, 3, true},
    {"rg_reference_uastc", 32, 32, 1, 3, false},
    {"ktx_document_uastc_rdo4_zstd5", 1024, 1024, 11, 4, true},
    {"color_grid_uastc_zstd", 1024, 1024, 1, 3, true},
    {"valid_R8G8B8A8_UNORM_2D_UASTC_ZSTD_9", 8, 8, 1, 4, false},
};

int full_chain(int w, int h) {
    int n = 1;
    while ((std::max(w, h) >> n) > 0) ++n;
    return n;
}

TEST(Ktx2Decoder, DecodesEveryConformanceFile) {
    for (const Expected& e : kFiles) {
        SCOPED_TRACE(e.name);
        const std::vector<uint8_t> bytes = test::read_ktx2(e.name);
        ASSERT_FALSE(bytes.empty());
        const TextureImage img = decode_ktx2(bytes, e.name, kLimit);
        EXPECT_EQ(img.width(), e.width);
        EXPECT_EQ(img.height(), e.height);
        EXPECT_EQ(img.channels(), e.channels);
        EXPECT_EQ(img.srgb(), e.srgb);
        EXPECT_EQ(img.levels(), full_chain(e.width, e.height));
        const TextureImage flat = decode_ktx2(bytes, e.name, kLimit, false);
        EXPECT_EQ(flat.levels(), 1);
        for (int c = 0; c < e.channels; ++c)
            EXPECT_EQ(flat.code(0, e.width / 2, e.height / 2, c),
                      img.code(0, e.width / 2, e.height / 2, c));
    }
}

// The glTF path: the same decoder behind decode_texture_image, only where
// KHR_texture_basisu allows KTX2.
TEST(Ktx2Decoder, TextureImagePathNeedsTheExtension) {
    const std::vector<uint8_t> bytes = test::read_ktx2("cyan_rgb_reference_uastc");
    TextureDecodeLimits limits;
    try {
        decode_texture_image(bytes, "a.ktx2", ImageEncoding::Srgb, limits);
        ADD_FAILURE();
    } catch (const ImageDecodeError& e) {
        EXPECT_EQ(e.why(), "not a PNG or JPEG image");
    }
    limits.allow_ktx2 = true;
    const TextureImage img = decode_texture_image(bytes, "a.ktx2", ImageEncoding::Srgb, limits);
    EXPECT_EQ(img.width(), 64);
}

// cyan_rgb_reference: every texel (0, 255, 255); UASTC codes a constant exactly.
TEST(Ktx2Decoder, CyanIsExact) {
    const TextureImage img = decode_ktx2(test::read_ktx2("cyan_rgb_reference_uastc"), "c", kLimit);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            ASSERT_EQ(img.code(0, x, y, 0), 0u);
            ASSERT_EQ(img.code(0, x, y, 1), 255u);
            ASSERT_EQ(img.code(0, x, y, 2), 255u);
        }
}

// rg_reference carries KTXswizzle = rg01: blue is 0 everywhere; green grows to the
// right and red upwards (top-left red, top-right yellow, bottom-left black).
TEST(Ktx2Decoder, RgSwizzleAndRamps) {
    const TextureImage img = decode_ktx2(test::read_ktx2("rg_reference_uastc"), "rg", kLimit);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) ASSERT_EQ(img.code(0, x, y, 2), 0u);
    EXPECT_GT(img.code(0, 0, 0, 0), 240u);
    EXPECT_LT(img.code(0, 0, 31, 0), 16u);
    EXPECT_LT(img.code(0, 0, 0, 1), 16u);
    EXPECT_GT(img.code(0, 31, 0, 1), 240u);
}

// rgba-mipmap-reference: each of the file's 7 levels is a solid colour of its own (red,
// orange, yellow, green, blue, cyan, magenta), so the pyramid comes from the file, level 0
// first, not from filtering level 0.
TEST(Ktx2Decoder, MipLevelsComeFromTheFile) {
    const TextureImage img =
        decode_ktx2(test::read_ktx2("rgba-mipmap-reference-basis"), "mips", kLimit);
    ASSERT_EQ(img.levels(), 7);
    const int expected[7][3] = {{255, 0, 0}, {255, 128, 0}, {255, 255, 0}, {0, 255, 0},
                                {0, 0, 255}, {0, 255, 255}, {255, 0, 255}};
    for (int l = 0; l < 7; ++l)
        for (int c = 0; c < 3; ++c) {
            SCOPED_TRACE("level " + std::to_string(l) + " channel " + std::to_string(c));
            // ETC1S's 5-bit base colours and modifiers: within 12 codes of the colour.
            const int got = int(img.code(l, img.width(l) / 2, img.height(l) / 2, c));
            EXPECT_NEAR(got, expected[l][c], 12);
        }
}

// Alpha: ETC1S's alpha slice and UASTC's per-block alpha. alpha_simple is half
// transparent everywhere; luminance_alpha's alpha ramps from 0 at the left to 255 at the
// right, its luminance from 255 at the top to 0 at the bottom.
TEST(Ktx2Decoder, AlphaOfBothKinds) {
    const TextureImage simple = decode_ktx2(test::read_ktx2("alpha_simple_basis"), "a", kLimit);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) EXPECT_NEAR(int(simple.code(0, x, y, 3)), 128, 2);
    const TextureImage la =
        decode_ktx2(test::read_ktx2("luminance_alpha_reference_basis"), "la", kLimit);
    EXPECT_LT(la.code(0, 0, 0, 3), 8u);
    EXPECT_GT(la.code(0, 31, 31, 3), 247u);
    EXPECT_GT(la.code(0, 0, 0, 0), 247u);
    EXPECT_LT(la.code(0, 0, 31, 0), 8u);
    // luminance: grey (R = G = B) everywhere.
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            ASSERT_EQ(la.code(0, x, y, 0), la.code(0, x, y, 1));
            ASSERT_EQ(la.code(0, x, y, 1), la.code(0, x, y, 2));
        }
    const TextureImage doc =
        decode_ktx2(test::read_ktx2("ktx_document_uastc_rdo4_zstd5"), "doc", kLimit);
    EXPECT_EQ(doc.code(0, 0, 0, 3), 0u);        // transparent outside the page
    EXPECT_EQ(doc.code(0, 512, 700, 3), 255u);  // opaque on it
}

// Two-channel ETC1S files carry RRR and GGG slices: the second slice is green, not
// alpha. alpha_simple's DFD relabelled so: its second slice (128) becomes green.
TEST(Ktx2Decoder, Etc1sSecondSliceAsGreen) {
    std::vector<uint8_t> b = test::read_ktx2("alpha_simple_basis");
    const uint32_t dfd = uint32_t(b[48]) | uint32_t(b[49]) << 8;
    uint8_t& channel = b[dfd + 4 + 24 + 16 + 3];  // sample 1's channelType (low 4 bits)
    ASSERT_EQ(channel & 0xF, 15);                 // AAA
    channel = uint8_t((channel & 0xF0) | 4);      // GGG
    const TextureImage img = decode_ktx2(b, "gg", kLimit);
    ASSERT_EQ(img.channels(), 3);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) EXPECT_NEAR(int(img.code(0, x, y, 1)), 128, 2);
}

double psnr(const TextureImage& a, const TextureImage& b, int channels) {
    double se = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            for (int c = 0; c < channels; ++c) {
                const double d = double(a.code(0, x, y, c)) - double(b.code(0, x, y, c));
                se += d * d;
            }
    const double mse = se / (double(a.width()) * a.height() * channels);
    return 10 * std::log10(255.0 * 255.0 / mse);
}

// The same pictures coded as ETC1S and as UASTC decode alike. ETC1S (a shared codebook
// of 5-bit colours with one 4-entry modifier per 4x4 block) is the lossier by far:
// encoders reach about 30-35 dB on photos and charts, UASTC 40-50 dB, so the two agree to
// ETC1S's error. Measured: color_grid 32.8 dB (RGB), ktx_document 43.1 dB (RGB) and 43.9 dB
// (RGBA). A channel swap, a flipped image or garbled blocks gives under 20 dB.
TEST(Ktx2Decoder, Etc1sAndUastcOfOnePictureAgree) {
    const TextureImage grid_e = decode_ktx2(test::read_ktx2("color_grid_basis"), "e", kLimit);
    const TextureImage grid_u = decode_ktx2(test::read_ktx2("color_grid_uastc_zstd"), "u", kLimit);
    EXPECT_GT(psnr(grid_e, grid_u, 3), 30.0);
    const TextureImage doc_e = decode_ktx2(test::read_ktx2("ktx_document_basis"), "e", kLimit);
    const TextureImage doc_u =
        decode_ktx2(test::read_ktx2("ktx_document_uastc_rdo4_zstd5"), "u", kLimit);
    EXPECT_GT(psnr(doc_e, doc_u, 3), 40.0);
    EXPECT_GT(psnr(doc_e, doc_u, 4), 40.0);
}

// The chart's orientation (KTXorientation = rd: the first row is the top): its H row,
// saturated colours, is at the top, and the greyish A row at the bottom; H1 and A1 are
// red, not blue (no channel swap).
TEST(Ktx2Decoder, ChartIsUpright) {
    const TextureImage grid = decode_ktx2(test::read_ktx2("color_grid_uastc_zstd"), "g", kLimit);
    const auto red_minus_blue = [&](int x, int y) {
        return int(grid.code(0, x, y, 0)) - int(grid.code(0, x, y, 2));
    };
    EXPECT_GT(red_minus_blue(8, 8), 80);    // H1's corner
    EXPECT_GT(red_minus_blue(8, 1015), 0);  // A1's corner
    EXPECT_LT(red_minus_blue(8, 1015), 40);
}

}  // namespace
}  // namespace penumbra
