#include "io/image/ktx2_container.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "io/image/ktx2_error.h"

namespace penumbra {

namespace {

constexpr uint8_t kIdentifier[12] = {0xAB, 'K',  'T',  'X',  ' ',  '2',
                                     '0',  0xBB, '\r', '\n', 0x1A, '\n'};
constexpr size_t kHeaderSize = 80, kLevelEntrySize = 24;
// KHR_DF colour models of the Basis Universal payloads, and the transfer functions.
constexpr uint32_t kModelEtc1s = 163, kModelUastc = 166;
constexpr uint32_t kTransferLinear = 1, kTransferSrgb = 2;
// Channel ids: ETC1S's second slice (AAA, or GGG in two-channel files); UASTC's RGBA and
// RRRG (colour and alpha).
constexpr uint32_t kEtc1sAlpha = 15, kEtc1sGreen = 4, kUastcRgba = 3, kUastcRrrg = 5;

uint32_t u32(const uint8_t* p) {
    return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}
uint64_t u64(const uint8_t* p) { return uint64_t(u32(p)) | uint64_t(u32(p + 4)) << 32; }

std::string str(uint64_t v) { return std::to_string(v); }

// [offset, offset + length) lies inside a file of `size` bytes, without overflow.
void check_range(const char* what, uint64_t offset, uint64_t length, size_t size) {
    if (offset > size || length > size - offset)
        throw Ktx2Error(std::string(what) + " (bytes " + str(offset) + " + " + str(length) +
                        ") lies outside the file of " + str(size) + " bytes");
}

// The Data Format Descriptor's basic block: colour model, transfer, flags, samples.
void read_dfd(const uint8_t* data, size_t size, uint32_t offset, uint32_t length, Ktx2Info& info) {
    check_range("the data format descriptor", offset, length, size);
    if (length < 4 + 24) throw Ktx2Error("the data format descriptor is too short");
    const uint8_t* d = data + offset;
    if (u32(d) != length)
        throw Ktx2Error("dfdTotalSize " + str(u32(d)) + " differs from dfdByteLength " +
                        str(length));
    const uint8_t* b = d + 4;
    const uint32_t vendor = u32(b) & 0x1FFFF, type = u32(b) >> 17;
    const uint32_t version = u32(b + 4) & 0xFFFF, block_size = u32(b + 4) >> 16;
    if (vendor != 0 || type != 0)
        throw Ktx2Error("the first descriptor block is not Khronos' basic block");
    if (version != 2) throw Ktx2Error("DFD version " + str(version) + " is not 2");
    if (block_size < 24 || block_size > length - 4 || (block_size - 24) % 16 != 0)
        throw Ktx2Error("DFD block size " + str(block_size) + " is invalid");
    const uint32_t model = b[8], transfer = b[10], flags = b[11];
    if (model == kModelEtc1s)
        info.codec = BasisCodec::Etc1s;
    else if (model == kModelUastc)
        info.codec = BasisCodec::Uastc;
    else
        throw Ktx2Error("DFD colour model " + str(model) + " is not ETC1S (163) or UASTC (166)");
    if (transfer != kTransferLinear && transfer != kTransferSrgb)
        throw Ktx2Error("DFD transfer function " + str(transfer) +
                        " is neither linear (1) nor sRGB (2)");
    info.srgb = transfer == kTransferSrgb;
    info.premultiplied = (flags & 1) != 0;
    if (b[12] != 3 || b[13] != 3 || b[14] != 0 || b[15] != 0)
        throw Ktx2Error("DFD texel block is not 4x4");
    const uint32_t samples = (block_size - 24) / 16;
    const uint32_t max_samples = info.codec == BasisCodec::Etc1s ? 2 : 1;
    if (samples < 1 || samples > max_samples)
        throw Ktx2Error("DFD has " + str(samples) + " samples; " +
                        (info.codec == BasisCodec::Etc1s ? "ETC1S has 1 or 2" : "UASTC has 1"));
    for (uint32_t s = 0; s < samples; ++s) {
        const uint32_t channel = (u32(b + 24 + 16 * s) >> 24) & 0xF;
        if (info.codec == BasisCodec::Etc1s && s == 1) {
            if (channel != kEtc1sAlpha && channel != kEtc1sGreen)
                throw Ktx2Error("ETC1S DFD's second sample is channel " + str(channel) +
                                ", not AAA (15) or GGG (4)");
            info.etc1s_second_slice = channel == kEtc1sAlpha ? 3 : 1;
            info.has_alpha = channel == kEtc1sAlpha;
        }
        if (info.codec == BasisCodec::Uastc && (channel == kUastcRgba || channel == kUastcRrrg))
            info.has_alpha = true;
    }
}

// The key/value data: KTXorientation and KTXswizzle are read; other keys are skipped.
void read_kvd(const uint8_t* data, size_t size, uint32_t offset, uint32_t length, Ktx2Info& info) {
    check_range("the key/value data", offset, length, size);
    const uint8_t* p = data + offset;
    uint32_t pos = 0;
    while (pos < length) {
        if (length - pos < 4) throw Ktx2Error("truncated key/value entry");
        const uint32_t n = u32(p + pos);
        pos += 4;
        if (n == 0 || n > length - pos) throw Ktx2Error("key/value entry runs past its data");
        const char* kv = reinterpret_cast<const char*>(p + pos);
        const size_t key_len = strnlen(kv, n);
        if (key_len == n) throw Ktx2Error("key/value entry has no terminated key");
        const std::string key(kv, key_len);
        std::string value(kv + key_len + 1, n - key_len - 1);
        while (!value.empty() && value.back() == '\0') value.pop_back();
        if (key == "KTXorientation") {
            if (value.size() < 2 || (value[0] != 'r' && value[0] != 'l') ||
                (value[1] != 'd' && value[1] != 'u'))
                throw Ktx2Error("KTXorientation '" + value + "' is not valid for 2D");
            if (value[0] == 'l')
                throw Ktx2Error("KTXorientation '" + value + "' (right to left) is not supported");
            info.bottom_up = value[1] == 'u';
        } else if (key == "KTXswizzle") {
            if (value.size() != 4 || value.find_first_not_of("rgba01") != std::string::npos)
                throw Ktx2Error("KTXswizzle '" + value + "' is not four of r, g, b, a, 0, 1");
            info.swizzle = value;
        }
        // Entries are padded to 4 bytes; in 64 bits, so that a huge n cannot wrap.
        pos = uint32_t(std::min<uint64_t>(length, (uint64_t(pos) + n + 3) & ~uint64_t(3)));
    }
}

}  // namespace

bool is_ktx2(const uint8_t* data, size_t size) {
    return size >= sizeof(kIdentifier) && std::memcmp(data, kIdentifier, sizeof(kIdentifier)) == 0;
}

Ktx2Info parse_ktx2(const uint8_t* data, size_t size, uint64_t max_pixels) {
    if (!is_ktx2(data, size)) throw Ktx2Error("not a KTX 2.0 file (identifier)");
    if (size < kHeaderSize) throw Ktx2Error("truncated KTX2 header");
    const uint32_t vk_format = u32(data + 12), type_size = u32(data + 16);
    const uint32_t width = u32(data + 20), height = u32(data + 24), depth = u32(data + 28);
    const uint32_t layers = u32(data + 32), faces = u32(data + 36), level_count = u32(data + 40);
    const uint32_t scheme = u32(data + 44);
    if (vk_format != 0)
        throw Ktx2Error("vkFormat " + str(vk_format) +
                        " is not supported: only Basis Universal (ETC1S, UASTC) KTX2 files are "
                        "decoded");
    if (type_size != 1) throw Ktx2Error("typeSize " + str(type_size) + " is not 1");
    if (faces == 6) throw Ktx2Error("cube maps are not supported (KHR_texture_basisu is 2D)");
    if (faces != 1) throw Ktx2Error("faceCount " + str(faces) + " is invalid");
    if (layers > 1)
        throw Ktx2Error("array textures (" + str(layers) +
                        " layers) are not supported (KHR_texture_basisu is 2D)");
    if (depth != 0) throw Ktx2Error("3D textures are not supported (KHR_texture_basisu is 2D)");
    if (width == 0 || height == 0)
        throw Ktx2Error("a " + str(width) + "x" + str(height) + " texture is not 2D");
    if (uint64_t(width) * height > max_pixels)
        throw Ktx2Error(str(width) + "x" + str(height) + " is more than the limit of " +
                        str(max_pixels) + " pixels (--max-texture-pixels)");
    int full_chain = 1;
    while ((std::max(width, height) >> full_chain) > 0) ++full_chain;
    if (level_count > uint32_t(full_chain))
        throw Ktx2Error("levelCount " + str(level_count) + " is more than the " + str(full_chain) +
                        " levels of a " + str(width) + "x" + str(height) + " texture");
    Ktx2Info info;
    info.width = width;
    info.height = height;
    if (scheme == 3) throw Ktx2Error("ZLIB supercompression is not supported");
    if (scheme > 2) throw Ktx2Error("supercompressionScheme " + str(scheme) + " is unknown");
    info.scheme = Supercompression(scheme);
    const uint32_t n_levels = std::max(level_count, 1u);
    if (size < kHeaderSize + kLevelEntrySize * n_levels) throw Ktx2Error("truncated level index");

    read_dfd(data, size, u32(data + 48), u32(data + 52), info);
    read_kvd(data, size, u32(data + 56), u32(data + 60), info);
    info.sgd_offset = u64(data + 64);
    info.sgd_length = u64(data + 72);
    check_range("the supercompression global data", info.sgd_offset, info.sgd_length, size);
    if (info.codec == BasisCodec::Etc1s && info.scheme != Supercompression::BasisLz)
        throw Ktx2Error("ETC1S data must be BasisLZ-supercompressed");
    if (info.codec == BasisCodec::Uastc && info.scheme == Supercompression::BasisLz)
        throw Ktx2Error("BasisLZ supercompression of UASTC data is invalid");
    if ((info.scheme == Supercompression::BasisLz) != (info.sgd_length > 0))
        throw Ktx2Error(info.scheme == Supercompression::BasisLz
                            ? "BasisLZ file without supercompression global data"
                            : "supercompression global data without BasisLZ");

    for (uint32_t l = 0; l < n_levels; ++l) {
        const uint8_t* e = data + kHeaderSize + kLevelEntrySize * l;
        Ktx2Level level{u64(e), u64(e + 8), u64(e + 16), std::max(1u, width >> l),
                        std::max(1u, height >> l)};
        const std::string what = "level " + str(l);
        check_range(what.c_str(), level.offset, level.length, size);
        const uint64_t block_bytes =
            uint64_t((level.width + 3) / 4) * ((level.height + 3) / 4) * 16;
        if (info.scheme == Supercompression::BasisLz) {
            if (level.uncompressed_length != 0)
                throw Ktx2Error(what + ": uncompressedByteLength must be 0 with BasisLZ");
        } else if (level.uncompressed_length != block_bytes) {
            throw Ktx2Error(what + ": uncompressedByteLength " + str(level.uncompressed_length) +
                            " is not the " + str(block_bytes) + " bytes of its UASTC blocks");
        }
        if (info.scheme == Supercompression::None && level.length != block_bytes)
            throw Ktx2Error(what + ": byteLength " + str(level.length) + " is not the " +
                            str(block_bytes) + " bytes of its UASTC blocks");
        if (level.length == 0) throw Ktx2Error(what + " is empty");
        info.levels.push_back(level);
    }
    return info;
}

}  // namespace penumbra
