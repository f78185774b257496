// A texture's texels at the precision of its file (8-bit, 16-bit or float), with only
// the file's channels, and its MIP pyramid (box-filtered in linear space). sRGB-encoded
// 8/16-bit colour is decoded per fetch through a table, so it stays 1-2 bytes a channel.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/image.h"
#include "core/math/mat3.h"
#include "core/math/vec.h"

namespace penumbra {

enum class TexelFormat : uint8_t { U8, U16, F32 };

class TextureImage {
public:
    TextureImage() = default;
    // Storage for a w x h image of 1-4 channels and, with mipmaps, every coarser level
    // (halved with floor, down to 1x1), allocated once: the decoder writes level 0
    // through level0_data(), then build_mips() fills the rest. srgb: channels other than
    // alpha are sRGB-encoded (colour textures of 8 or 16 bits; ignored for F32).
    TextureImage(int width, int height, int channels, TexelFormat format, bool srgb,
                 bool mipmaps = true);
    // A float texture from a linear Image (tests, generated data), pyramid built.
    explicit TextureImage(const Image& image, bool mipmaps = true);

    void* level0_data();
    // A level's storage (row-major, channels interleaved), for decoders whose files carry
    // their own pyramid (KTX2); build_mips(first) then fills only the levels they lack.
    void* level_data(int level);
    // Each level from first_level on from the one before: the box filter over each output
    // texel's exact area in the finer level (fractional weights at odd sizes), averaged in
    // linear space and re-encoded to the nearest code. Parallel over rows (TBB).
    void build_mips(int first_level = 1);

    int width(int level = 0) const { return m_levels[size_t(level)].width; }
    int height(int level = 0) const { return m_levels[size_t(level)].height; }
    int levels() const { return int(m_levels.size()); }
    int channels() const { return m_channels; }
    TexelFormat format() const { return m_format; }
    bool srgb() const { return m_srgb; }
    bool empty() const { return m_levels.empty() || m_levels[0].width == 0; }

    // Texel (x, y) of a level (in range), decoded to linear RGBA as Image::rgba reads
    // channels (gray fills RGB, missing alpha is 1). No working-space matrix.
    Vec4 texel(int level, int x, int y) const;
    // The bilinear blend of texels (x0, y0), (x1, y0), (x0, y1), (x1, y1) of a level with
    // weights (1 - ax)(1 - ay), ax (1 - ay), (1 - ax) ay, ax ay, summed in that order:
    // texture lookups' inner loop, with the format's decoding chosen once for the four.
    Vec4 bilinear(int level, int x0, int x1, int y0, int y1, float ax, float ay) const;
    // One level decoded to a linear float Image of the same channels (tests, previews).
    Image to_image(int level = 0) const;
    // The stored code of one channel (tests: precision and rounding).
    uint32_t code(int level, int x, int y, int c) const;

    // Bytes of texel storage, all levels (what the store costs; the object is small).
    size_t bytes() const;
    size_t texel_count() const { return m_levels.empty() ? 0 : size_t(width()) * height(); }

    // The scene's working-space conversion for colour textures (io/color/scene_color.cpp):
    // applied to RGB after filtering, which is linear, so it commutes with the filter.
    void set_color_matrix(const Mat3& m) { m_matrix = m; }
    const std::optional<Mat3>& color_matrix() const { return m_matrix; }

    std::string name;  // file name or glTF element, for messages

private:
    struct Level {
        int width = 0, height = 0;
        size_t offset = 0;  // first element of the level in the format's store
    };
    size_t index(int level, int x, int y) const {
        const Level& l = m_levels[size_t(level)];
        return l.offset + (size_t(y) * size_t(l.width) + size_t(x)) * size_t(m_channels);
    }
    float linear(size_t i, int c) const;  // element i, channel c, decoded
    Vec4 texel_u8(size_t i) const;         // texel at element i of an 8-bit store
    void store(size_t i, int c, float v);  // encoded to the nearest code
    void downsample(int level);           // level from level - 1

    std::vector<Level> m_levels;
    int m_channels = 0;
    TexelFormat m_format = TexelFormat::F32;
    bool m_srgb = false;
    std::vector<uint8_t> m_u8;
    std::vector<uint16_t> m_u16;
    std::vector<float> m_f32;
    std::optional<Mat3> m_matrix;
    // 8-bit stores: each channel's decoded value per code (the sRGB table or code / 255,
    // the values linear() computes), so a fetch is one load a channel, no branches.
    const float* m_u8_lut[4] = {nullptr, nullptr, nullptr, nullptr};
};

// The sRGB transfer (IEC 61966-2-1, with OCIO's continuous toe), decoded for every 8-bit
// and 16-bit code (computed in double).
float srgb8_to_linear(uint8_t code);
float srgb16_to_linear(uint16_t code);

}  // namespace penumbra
