// Basis Universal's building blocks with analytic answers: canonical Huffman decoding,
// its validation, and a UASTC solid-colour block.
#include <gtest/gtest.h>

#include "io/image/basis_huffman.h"
#include "io/image/basis_uastc.h"
#include "io/image/ktx2_error.h"

namespace penumbra {
namespace {

// Lengths {2, 2, 2, 2}: codes 00, 01, 10, 11 in symbol order, read most significant bit
// first from a least-significant-bit-first stream.
TEST(BasisHuffman, CanonicalCodesDecode) {
    const HuffmanTable t({2, 2, 2, 2});
    const uint8_t bits[1] = {0b11100001};  // codes 10, 00, 01, 11 (first bit lowest)
    BitReader in(bits, 1);
    EXPECT_EQ(t.decode(in), 2u);
    EXPECT_EQ(t.decode(in), 0u);
    EXPECT_EQ(t.decode(in), 1u);
    EXPECT_EQ(t.decode(in), 3u);
    EXPECT_THROW(t.decode(in), Ktx2Error);  // the stream has ended
}

TEST(BasisHuffman, InvalidTablesAreRefused) {
    EXPECT_THROW(HuffmanTable({1, 1, 1}), Ktx2Error);  // over-subscribed
    EXPECT_THROW(HuffmanTable({17, 1}), Ktx2Error);    // longer than 16 bits
    const HuffmanTable incomplete({1});                // code 0 only: 1 matches nothing
    const uint8_t one[2] = {0xFF, 0xFF};
    BitReader in(one, 2);
    EXPECT_THROW(incomplete.decode(in), Ktx2Error);
    BitReader empty_in(one, 2);
    EXPECT_THROW(HuffmanTable().decode(empty_in), Ktx2Error);
}

// Mode 8 (prefix 10111): RGBA as four bytes after the prefix, every texel that colour.
TEST(BasisUastc, SolidColourBlock) {
    uint8_t block[16] = {};
    const uint32_t rgba = 0x80C04020;  // R 0x20, G 0x40, B 0xC0, A 0x80
    const uint64_t bits = 0x17 | uint64_t(rgba) << 5;
    for (int i = 0; i < 8; ++i) block[i] = uint8_t(bits >> (8 * i));
    uint8_t out[64];
    decode_uastc_block(block, out);
    for (int t = 0; t < 16; ++t) {
        EXPECT_EQ(out[t * 4 + 0], 0x20);
        EXPECT_EQ(out[t * 4 + 1], 0x40);
        EXPECT_EQ(out[t * 4 + 2], 0xC0);
        EXPECT_EQ(out[t * 4 + 3], 0x80);
    }
}

TEST(BasisUastc, ReservedModeIsAnError) {
    uint8_t block[16] = {69};  // prefix 1000101: the reserved 20th mode
    uint8_t out[64];
    EXPECT_THROW(decode_uastc_block(block, out), Ktx2Error);
}

}  // namespace
}  // namespace penumbra
