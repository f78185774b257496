// The fixed data of UASTC (UASTC Texture Specification): the modes, the mode prefix
// decoding table, BISE ranges with ASTC's unquantisation constants, and the partition
// patterns with their anchor texels. Internal to basis_uastc.cpp.
#pragma once

#include <cstdint>

namespace penumbra::uastc {

enum class Layout : uint8_t { Rgb, Rgba, La };

struct Mode {
    uint8_t prefix_bits;     // length of the mode's prefix code
    uint8_t endpoint_range;  // BISE range index of the endpoints
    Layout layout;
    uint8_t weight_bits;
    uint8_t planes;
    uint8_t subsets;
    uint8_t hint_bits;  // transcoding hints after the prefix (BC1, ETC1, ETC2 alpha)
};

// Modes 0-18; mode 8 is a solid colour (void extent) and uses no field but prefix_bits.
constexpr Mode kModes[19] = {
    {4, 19, Layout::Rgb, 4, 1, 1, 15},  {6, 20, Layout::Rgb, 2, 1, 1, 15},
    {5, 8, Layout::Rgb, 3, 1, 2, 15},   {5, 7, Layout::Rgb, 2, 1, 3, 15},
    {5, 12, Layout::Rgb, 2, 1, 2, 15},  {5, 20, Layout::Rgb, 3, 1, 1, 15},
    {5, 18, Layout::Rgb, 2, 2, 1, 15},  {5, 12, Layout::Rgb, 2, 1, 2, 15},
    {5, 0, Layout::Rgba, 0, 0, 0, 0},   {5, 8, Layout::Rgba, 2, 1, 2, 23},
    {3, 13, Layout::Rgba, 4, 1, 1, 17}, {2, 13, Layout::Rgba, 2, 2, 1, 17},
    {3, 19, Layout::Rgba, 3, 1, 1, 17}, {5, 20, Layout::Rgba, 1, 2, 1, 23},
    {5, 20, Layout::Rgba, 2, 1, 1, 23}, {7, 20, Layout::La, 4, 1, 1, 23},
    {6, 20, Layout::La, 2, 1, 2, 23},   {6, 20, Layout::La, 2, 2, 1, 23},
    {4, 11, Layout::Rgb, 5, 1, 1, 15},
};

// The mode of each value of a block's low 7 bits (19: reserved).
constexpr uint8_t kModeOfPrefix[128] = {
    11, 0,  10, 3,  11, 15, 12, 7,  11, 18, 10, 5,  11, 14, 12, 9,  11, 0,  10, 4,  11, 16,
    12, 8,  11, 18, 10, 6,  11, 2,  12, 13, 11, 0,  10, 3,  11, 17, 12, 7,  11, 18, 10, 5,
    11, 14, 12, 9,  11, 0,  10, 4,  11, 1,  12, 8,  11, 18, 10, 6,  11, 2,  12, 13, 11, 0,
    10, 3,  11, 19, 12, 7,  11, 18, 10, 5,  11, 14, 12, 9,  11, 0,  10, 4,  11, 16, 12, 8,
    11, 18, 10, 6,  11, 2,  12, 13, 11, 0,  10, 3,  11, 17, 12, 7,  11, 18, 10, 5,  11, 14,
    12, 9,  11, 0,  10, 4,  11, 1,  12, 8,  11, 18, 10, 6,  11, 2,  12, 13};

// A BISE range: plain bits, with a trit or a quint; ASTC's colour unquantisation takes
// B's 9 bits from the plain bits ('a' the lowest, '0' a zero) and the multiplier C.
struct BiseRange {
    uint8_t bits, trits, quints;
    const char* b;
    uint8_t c;
};
constexpr BiseRange kBise[21] = {
    {1, 0, 0, "", 0},
    {0, 1, 0, "", 0},
    {2, 0, 0, "", 0},
    {0, 0, 1, "", 0},
    {1, 1, 0, "000000000", 204},
    {3, 0, 0, "", 0},
    {1, 0, 1, "000000000", 113},
    {2, 1, 0, "b000b0bb0", 93},
    {4, 0, 0, "", 0},
    {2, 0, 1, "b0000bb00", 54},
    {3, 1, 0, "cb000cbcb", 44},
    {5, 0, 0, "", 0},
    {3, 0, 1, "cb0000cbc", 26},
    {4, 1, 0, "dcb000dcb", 22},
    {6, 0, 0, "", 0},
    {4, 0, 1, "dcb0000dc", 13},
    {5, 1, 0, "edcb000ed", 11},
    {7, 0, 0, "", 0},
    {5, 0, 1, "edcb0000e", 6},
    {6, 1, 0, "fedcb000f", 5},
    {8, 0, 0, "", 0},
};

// Partition patterns (subset of each texel, row-major) and each subset's anchor texel,
// whose weight is sent without its top bit: 2 subsets (30), 3 subsets (11), and mode 7's
// 2-subset patterns taken from 3-subset BC7 partitions (19).
constexpr int kPatterns2 = 30, kPatterns3 = 11, kPatterns7 = 19;
extern const uint8_t kPattern2[kPatterns2][16], kAnchor2[kPatterns2][2];
extern const uint8_t kPattern3[kPatterns3][16], kAnchor3[kPatterns3][3];
extern const uint8_t kPattern7[kPatterns7][16], kAnchor7[kPatterns7][2];

}  // namespace penumbra::uastc
