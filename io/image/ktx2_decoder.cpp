#include "io/image/ktx2_decoder.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <zstd.h>

#include <algorithm>
#include <cstring>
#include <memory>

#include "io/image/basis_etc1s.h"
#include "io/image/basis_uastc.h"
#include "io/image/ktx2_container.h"
#include "io/image/ktx2_error.h"
#include "io/image/image_reader.h"

namespace penumbra {

namespace {

// A level's UASTC blocks, Zstandard-decompressed when the file is supercompressed (to
// exactly the byte count the level index promises, which parse_ktx2 bounded).
std::vector<uint8_t> uastc_blocks(const uint8_t* file, const Ktx2Info& info, const Ktx2Level& l) {
    const uint8_t* src = file + l.offset;
    if (info.scheme == Supercompression::None) return std::vector<uint8_t>(src, src + l.length);
    std::vector<uint8_t> out(size_t(l.uncompressed_length));
    const size_t n = ZSTD_decompress(out.data(), out.size(), src, size_t(l.length));
    if (ZSTD_isError(n)) throw Ktx2Error(std::string("Zstandard: ") + ZSTD_getErrorName(n));
    if (n != out.size())
        throw Ktx2Error("Zstandard data decompresses to " + std::to_string(n) + " bytes, not " +
                        std::to_string(out.size()));
    return out;
}

void decode_uastc_level(const std::vector<uint8_t>& blocks, uint32_t w, uint32_t h, uint8_t* rgba) {
    const uint32_t bw = (w + 3) / 4, bh = (h + 3) / 4;
    tbb::parallel_for(
        tbb::blocked_range<uint32_t>(0, bh), [&](const tbb::blocked_range<uint32_t>& r) {
            uint8_t texels[64];
            for (uint32_t by = r.begin(); by < r.end(); ++by)
                for (uint32_t bx = 0; bx < bw; ++bx) {
                    decode_uastc_block(&blocks[(size_t(by) * bw + bx) * 16], texels);
                    for (uint32_t y = 0; y < 4 && by * 4 + y < h; ++y)
                        for (uint32_t x = 0; x < 4 && bx * 4 + x < w; ++x)
                            std::memcpy(rgba + (size_t(by * 4 + y) * w + bx * 4 + x) * 4,
                                        texels + (y * 4 + x) * 4, 4);
                }
        });
}

// RGBA texels into the level's storage: swizzled, `channels` of them, rows flipped for a
// bottom-up file.
void store_level(const std::vector<uint8_t>& rgba, uint32_t w, uint32_t h, const Ktx2Info& info,
                 int channels, uint8_t* dst) {
    int source[4];
    for (int c = 0; c < 4; ++c) {
        const char s = info.swizzle[size_t(c)];
        source[c] = s == 'r' ? 0 : s == 'g' ? 1 : s == 'b' ? 2 : s == 'a' ? 3 : s == '0' ? 4 : 5;
    }
    for (uint32_t y = 0; y < h; ++y) {
        const uint8_t* row = rgba.data() + size_t(info.bottom_up ? h - 1 - y : y) * w * 4;
        uint8_t* out = dst + size_t(y) * w * size_t(channels);
        for (uint32_t x = 0; x < w; ++x, row += 4, out += channels)
            for (int c = 0; c < channels; ++c)
                out[c] = source[c] < 4 ? row[source[c]] : source[c] == 4 ? 0 : 255;
    }
}

TextureImage decode(const std::vector<uint8_t>& bytes, uint64_t max_pixels, bool mipmaps) {
    const Ktx2Info info = parse_ktx2(bytes.data(), bytes.size(), max_pixels);
    // Alpha that stays in the texture: the file's, unless the swizzle replaces it.
    const bool alpha = info.swizzle[3] == '1' ? false : info.has_alpha || info.swizzle[3] == '0';
    if (info.premultiplied && alpha)
        throw Ktx2Error(
            "premultiplied alpha is not supported (glTF textures have straight "
            "alpha)");
    const int channels = alpha ? 4 : 3;
    TextureImage img(int(info.width), int(info.height), channels, TexelFormat::U8, info.srgb,
                     mipmaps);
    const int levels = std::min(int(info.levels.size()), img.levels());
    std::unique_ptr<BasisLzDecoder> basis;
    if (info.codec == BasisCodec::Etc1s)
        basis = std::make_unique<BasisLzDecoder>(
            bytes.data() + info.sgd_offset, size_t(info.sgd_length), uint32_t(info.levels.size()));
    std::vector<uint8_t> rgba;
    for (int l = 0; l < levels; ++l) {
        const Ktx2Level& level = info.levels[size_t(l)];
        rgba.assign(size_t(level.width) * level.height * 4, 0);
        if (basis)
            basis->decode(uint32_t(l), bytes.data() + level.offset, size_t(level.length),
                          level.width, level.height, info.etc1s_second_slice, rgba.data());
        else
            decode_uastc_level(uastc_blocks(bytes.data(), info, level), level.width, level.height,
                               rgba.data());
        store_level(rgba, level.width, level.height, info, channels,
                    static_cast<uint8_t*>(img.level_data(l)));
    }
    img.build_mips(levels);
    return img;
}

}  // namespace

TextureImage decode_ktx2(const std::vector<uint8_t>& bytes, const std::string& name,
                         uint64_t max_pixels, bool mipmaps) {
    try {
        return decode(bytes, max_pixels, mipmaps);
    } catch (const Ktx2Error& e) {
        throw ImageDecodeError(name, std::string("KTX2: ") + e.what());
    } catch (const std::bad_alloc&) {
        throw ImageDecodeError(name, "KTX2: out of memory");
    }
}

}  // namespace penumbra
