// Corrupt and unsupported KTX2 files: each is an ImageDecodeError naming the image,
// never a crash or an unbounded allocation (these tests also run under ASan:
// scripts/sanitize.sh).
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "io/image/ktx2_decoder.h"
#include "io/image/image_reader.h"
#include "tests/io/image/ktx2_test_files.h"

namespace penumbra {
namespace {

constexpr uint64_t kLimit = kDefaultMaxTexturePixels;

// The reason decoding `bytes` fails with, or "" when it succeeds.
std::string failure(const std::vector<uint8_t>& bytes, uint64_t limit = kLimit) {
    try {
        decode_ktx2(bytes, "t.ktx2", limit);
        return "";
    } catch (const ImageDecodeError& e) {
        EXPECT_EQ(std::string(e.what()), "t.ktx2: cannot decode image: " + e.why());
        return e.why();
    }
}

void put32(std::vector<uint8_t>& b, size_t at, uint32_t v) {
    for (int i = 0; i < 4; ++i) b[at + size_t(i)] = uint8_t(v >> (8 * i));
}
void put64(std::vector<uint8_t>& b, size_t at, uint64_t v) {
    put32(b, at, uint32_t(v));
    put32(b, at + 4, uint32_t(v >> 32));
}
uint32_t get32(const std::vector<uint8_t>& b, size_t at) {
    uint32_t v;
    std::memcpy(&v, &b[at], 4);
    return v;
}

TEST(Ktx2Corrupt, CubeMapsAndArraysAreRefusedByName) {
    EXPECT_EQ(failure(test::read_ktx2("output_R8G8B8_SRGB_CUBE")),
              "KTX2: cube maps are not supported (KHR_texture_basisu is 2D)");
    EXPECT_EQ(failure(test::read_ktx2("output_blze_0_psnr_2d_array_r8g8b8a8_unorm")),
              "KTX2: array textures (2 layers) are not supported (KHR_texture_basisu is 2D)");
}

TEST(Ktx2Corrupt, UnsupportedHeaderFields) {
    const std::vector<uint8_t> good = test::read_ktx2("alpha_simple_basis");
    std::vector<uint8_t> b = good;
    put32(b, 12, 37);  // VK_FORMAT_R8G8B8A8_UNORM
    EXPECT_EQ(failure(b),
              "KTX2: vkFormat 37 is not supported: only Basis Universal (ETC1S, "
              "UASTC) KTX2 files are decoded");
    b = good;
    put32(b, 28, 4);
    EXPECT_EQ(failure(b), "KTX2: 3D textures are not supported (KHR_texture_basisu is 2D)");
    b = good;
    put32(b, 44, 3);
    EXPECT_EQ(failure(b), "KTX2: ZLIB supercompression is not supported");
    b = good;
    put32(b, 40, 5);  // an 8x8 texture has 4 levels at most
    EXPECT_EQ(failure(b), "KTX2: levelCount 5 is more than the 4 levels of a 8x8 texture");
    b = good;
    b[get32(b, 48) + 4 + 11] |= 1;  // DFD flags: KHR_DF_FLAG_ALPHA_PREMULTIPLIED
    EXPECT_EQ(failure(b),
              "KTX2: premultiplied alpha is not supported (glTF textures have "
              "straight alpha)");
    b = good;
    b[get32(b, 48) + 4 + 10] = 13;  // DFD transfer function: PQ
    EXPECT_EQ(failure(b), "KTX2: DFD transfer function 13 is neither linear (1) nor sRGB (2)");
}

TEST(Ktx2Corrupt, OversizeDimensionsAreRefusedBeforeAllocating) {
    std::vector<uint8_t> b = test::read_ktx2("color_grid_basis");
    put32(b, 20, 1u << 20);
    put32(b, 24, 1u << 20);
    EXPECT_EQ(failure(b),
              "KTX2: 1048576x1048576 is more than the limit of 268435456 pixels "
              "(--max-texture-pixels)");
    EXPECT_EQ(failure(test::read_ktx2("cyan_rgb_reference_uastc"), 1000),
              "KTX2: 64x64 is more than the limit of 1000 pixels (--max-texture-pixels)");
}

TEST(Ktx2Corrupt, RangesOutsideTheFile) {
    const std::vector<uint8_t> good = test::read_ktx2("ktx_document_basis");
    std::vector<uint8_t> b = good;
    put64(b, 80, ~uint64_t(0) - 8);  // level 0's byteOffset: overflows with its length
    EXPECT_NE(failure(b).find("level 0 (bytes"), std::string::npos) << failure(b);
    b = good;
    put32(b, 52, 1u << 30);  // dfdByteLength
    EXPECT_NE(failure(b).find("the data format descriptor (bytes"), std::string::npos);
    b = good;
    put32(b, 60, 1u << 30);  // kvdByteLength
    EXPECT_NE(failure(b).find("the key/value data (bytes"), std::string::npos);
    b = good;
    put64(b, 64, b.size());  // sgdByteOffset at the end, length unchanged
    EXPECT_NE(failure(b).find("the supercompression global data (bytes"), std::string::npos);
    b = good;
    put32(b, size_t(get32(b, 64)) + 20 + 4, 1u << 30);  // image 0's rgbSliceByteOffset
    EXPECT_EQ(failure(b), "KTX2: BasisLZ RGB slice lies outside its level");
}

// Every prefix of small files, and regularly spaced prefixes of large ones: truncated
// headers, indexes, codebooks, slices and Zstandard frames.
TEST(Ktx2Corrupt, TruncatedFilesFail) {
    for (const char* name : {"alpha_simple_basis", "valid_R8G8B8A8_UNORM_2D_UASTC_ZSTD_9",
                             "rg_reference_uastc", "ktx_document_basis", "color_grid_uastc_zstd"}) {
        SCOPED_TRACE(name);
        const std::vector<uint8_t> good = test::read_ktx2(name);
        const size_t step = good.size() < 2000 ? 1 : good.size() / 300;
        for (size_t n = 0; n < good.size(); n += step)
            EXPECT_NE(failure(std::vector<uint8_t>(good.begin(), good.begin() + long(n))), "") << n;
    }
}

// Codebooks and Huffman tables overwritten: the endpoint codebook's tables made
// over-subscribed (all code lengths 7), the slice tables zeroed.
TEST(Ktx2Corrupt, BadHuffmanDataFails) {
    const std::vector<uint8_t> good = test::read_ktx2("ktx_document_basis");
    const size_t sgd = get32(good, 64);
    const uint32_t levels = get32(good, 40);
    const size_t endpoints = sgd + 20 + 20 * levels;
    const size_t selectors = endpoints + get32(good, sgd + 4);
    const size_t tables = selectors + get32(good, sgd + 8);
    std::vector<uint8_t> b = good;
    std::memset(&b[endpoints], 0xFF, get32(good, sgd + 4));
    EXPECT_NE(failure(b), "");
    b = good;
    std::memset(&b[tables], 0x00, get32(good, sgd + 12));
    EXPECT_NE(failure(b), "");
    b = good;
    std::memset(&b[selectors], 0xA5, get32(good, sgd + 8));
    EXPECT_NE(failure(b), "");
}

// Random bytes changed (fixed seed) anywhere in an ETC1S and a UASTC+Zstandard file:
// each either decodes or fails cleanly.
TEST(Ktx2Corrupt, RandomDamageNeverCrashes) {
    std::mt19937 rng(44);
    int failed = 0, total = 0;
    for (const char* name : {"alpha_simple_basis", "rgba-mipmap-reference-basis",
                             "valid_R8G8B8A8_UNORM_2D_UASTC_ZSTD_9", "rg_reference_uastc"}) {
        const std::vector<uint8_t> good = test::read_ktx2(name);
        for (int trial = 0; trial < 400; ++trial, ++total) {
            std::vector<uint8_t> b = good;
            const int changes = 1 + int(rng() % 4);
            for (int k = 0; k < changes; ++k) b[rng() % b.size()] = uint8_t(rng());
            failed += failure(b).empty() ? 0 : 1;
        }
    }
    EXPECT_GT(failed, 0);
    EXPECT_LT(failed, total);
}

}  // namespace
}  // namespace penumbra
