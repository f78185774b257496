// The KTX 2.0 container (Khronos KTX File Format Specification 2.0): the header, the
// level index, the basic block of the Data Format Descriptor, the key/value data and the
// supercompression global data, every field checked against the file's size and against
// what a 2D Basis Universal texture (KHR_texture_basisu) may be, before any allocation.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace penumbra {

enum class BasisCodec { Etc1s, Uastc };
enum class Supercompression : uint32_t { None = 0, BasisLz = 1, Zstd = 2 };

struct Ktx2Level {
    uint64_t offset = 0, length = 0, uncompressed_length = 0;  // in the file
    uint32_t width = 0, height = 0;
};

struct Ktx2Info {
    uint32_t width = 0, height = 0;
    BasisCodec codec = BasisCodec::Etc1s;
    Supercompression scheme = Supercompression::None;
    bool srgb = false;           // DFD transfer function: sRGB (else linear)
    bool premultiplied = false;  // DFD flag KHR_DF_FLAG_ALPHA_PREMULTIPLIED
    bool has_alpha = false;      // ETC1S: an alpha slice; UASTC: RGBA or RRRG channels
    // ETC1S: the channel a second slice holds (DFD sample AAA: 3, alpha; GGG: 1, green in
    // two-channel files), or -1 for an RGB slice alone.
    int etc1s_second_slice = -1;
    bool bottom_up = false;        // KTXorientation "ru": the first row is the bottom one
    std::string swizzle = "rgba";  // KTXswizzle, or the identity
    uint64_t sgd_offset = 0, sgd_length = 0;
    std::vector<Ktx2Level> levels;  // level 0 (the largest) first
};

// Parses and validates the container of `size` bytes. Refuses (Ktx2Error, saying what)
// anything but a 2D texture of one layer and one face coded as BasisLZ/ETC1S or UASTC:
// cube maps, arrays, 3D textures and other vkFormats included; a level count greater
// than the full chain; a level, DFD, key/value or global-data range outside the file;
// and more than max_pixels pixels at level 0.
Ktx2Info parse_ktx2(const uint8_t* data, size_t size, uint64_t max_pixels);

// True when the bytes start with the KTX 2.0 identifier.
bool is_ktx2(const uint8_t* data, size_t size);

}  // namespace penumbra
