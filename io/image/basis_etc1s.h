// BasisLZ/ETC1S, the KTX2 payload of Basis Universal's ETC1S mode (KTX 2.0 specification,
// "Basis Universal Global Data" and the ETC1S slice format): the global data holds one
// endpoint and one selector codebook, four Huffman tables and an image descriptor per
// image; each level holds an RGB slice and, for RGBA textures, an alpha slice of
// codebook indices. Decoded straight to 8-bit RGBA (no transcoding to a GPU format).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "io/image/basis_huffman.h"

namespace penumbra {

class BasisLzDecoder {
public:
    // Reads the supercompression global data of a file of `image_count` images (one per
    // level for a 2D texture). Throws Ktx2Error on lengths that do not add up, a corrupt
    // codebook or table, or a global selector codebook (not allowed in KTX2).
    BasisLzDecoder(const uint8_t* sgd, size_t sgd_size, uint32_t image_count);

    // Decodes image `image` from its level's bytes into `rgba` (width x height x 4,
    // rows top to bottom as stored): the RGB slice, and the second slice (alpha, or green
    // in two-channel files) into channel `second` unless it is -1 (A = 255 otherwise).
    // Throws Ktx2Error on a corrupt slice.
    void decode(uint32_t image, const uint8_t* level, size_t level_size, uint32_t width,
                uint32_t height, int second, uint8_t* rgba) const;

private:
    struct ImageDesc {
        uint32_t flags, rgb_offset, rgb_length, alpha_offset, alpha_length;
    };
    void read_endpoints(const uint8_t* data, size_t size, uint32_t count);
    void read_selectors(const uint8_t* data, size_t size, uint32_t count);
    void read_tables(const uint8_t* data, size_t size);
    // Decodes one slice's blocks; calls out(block_x, block_y, endpoint, selector).
    template <class Out>
    void decode_slice(const uint8_t* data, size_t size, uint32_t blocks_x, uint32_t blocks_y,
                      Out out) const;

    std::vector<std::array<uint8_t, 12>> m_endpoint_colors;  // 4 RGB colours per endpoint
    std::vector<std::array<uint8_t, 4>> m_selectors;         // 2-bit selectors, a byte a row
    std::vector<ImageDesc> m_images;
    HuffmanTable m_endpoint_pred, m_endpoint_delta, m_selector, m_selector_rle;
    uint32_t m_history_size = 0;
};

}  // namespace penumbra
