#include "io/image/image_header.h"

#include <cstring>

namespace penumbra {

namespace {

uint32_t be16(const uint8_t* p) { return uint32_t(p[0]) << 8 | p[1]; }
uint32_t be32(const uint8_t* p) { return be16(p) << 16 | be16(p + 2); }
uint32_t le16(const uint8_t* p) { return uint32_t(p[1]) << 8 | p[0]; }
uint32_t le24(const uint8_t* p) { return uint32_t(p[2]) << 16 | le16(p); }
uint32_t le32(const uint8_t* p) { return uint32_t(p[3]) << 24 | le24(p); }

bool starts(const std::vector<uint8_t>& b, const char* magic, size_t offset = 0) {
    const size_t n = std::strlen(magic);
    return b.size() >= offset + n && std::memcmp(b.data() + offset, magic, n) == 0;
}

ImageHeader refused(ImageFormat format, const std::string& problem) {
    ImageHeader h;
    h.format = format;
    h.problem = problem;
    return h;
}

// PNG: the 8-byte signature, then IHDR first with width and height as big-endian
// 31-bit values (PNG spec, sections 5.2 and 11.2.2).
ImageHeader png_header(const std::vector<uint8_t>& b) {
    if (b.size() < 24) return refused(ImageFormat::Png, "truncated PNG header (no IHDR)");
    if (!starts(b, "IHDR", 12))
        return refused(ImageFormat::Png, "malformed PNG header (the first chunk is not IHDR)");
    ImageHeader h;
    h.format = ImageFormat::Png;
    h.width = be32(&b[16]);
    h.height = be32(&b[20]);
    if (h.width > 0x7fffffffu || h.height > 0x7fffffffu)
        h.problem = "PNG header has a dimension above 2^31 - 1";
    // Chunks (length, type, data, CRC) up to IEND: a file cut short is named here rather
    // than by libpng, which prints its own line to stderr (PNG spec, section 5.3).
    bool idat = false;
    for (size_t at = 8; h.problem.empty();) {
        if (at + 12 > b.size()) {
            h.problem = "truncated PNG (it ends before IEND)";
            break;
        }
        const uint64_t end = uint64_t(at) + 12 + be32(&b[at]);
        const std::string type(reinterpret_cast<const char*>(&b[at + 4]), 4);
        if (end > b.size())
            h.problem = "truncated PNG (its " + type + " chunk runs past the end of the data)";
        else if (type == "IEND" && !idat)
            h.problem = "malformed PNG (no IDAT chunk before IEND)";
        if (type == "IEND") break;
        idat = idat || type == "IDAT";
        at = size_t(end);
    }
    return h;
}

// JPEG: markers up to the first start-of-frame (SOF0-SOF15 but DHT C4, JPG C8, DAC CC),
// whose segment holds precision, height, width (ITU T.81, B.2.2). Height 0 (set later
// by a DNL marker) is refused like any zero dimension.
ImageHeader jpeg_header(const std::vector<uint8_t>& b) {
    size_t i = 2;
    while (i + 1 < b.size()) {
        if (b[i] != 0xFF) return refused(ImageFormat::Jpeg, "malformed JPEG marker");
        const uint8_t m = b[i + 1];
        if (m == 0xFF) {  // fill byte
            ++i;
            continue;
        }
        i += 2;
        if (m == 0x01 || (m >= 0xD0 && m <= 0xD7)) continue;  // no length field
        if (m == 0xD9 || m == 0xDA) break;                    // EOI or SOS before a SOF
        if (i + 2 > b.size()) break;
        const uint32_t len = be16(&b[i]);
        if (len < 2) return refused(ImageFormat::Jpeg, "malformed JPEG segment length");
        if (m >= 0xC0 && m <= 0xCF && m != 0xC4 && m != 0xC8 && m != 0xCC) {
            if (len < 7 || i + 7 > b.size()) break;
            ImageHeader h;
            h.format = ImageFormat::Jpeg;
            h.height = be16(&b[i + 3]);
            h.width = be16(&b[i + 5]);
            return h;
        }
        i += len;
    }
    return refused(ImageFormat::Jpeg, "truncated JPEG header (no frame header)");
}

// WebP: RIFF "WEBP" and a first chunk VP8 (lossy: 14-bit sizes after the start code),
// VP8L (lossless: 14-bit sizes minus one) or VP8X (extended: 24-bit canvas sizes minus
// one). Google's WebP container and lossless bitstream specifications.
ImageHeader webp_header(const std::vector<uint8_t>& b) {
    ImageHeader h;
    h.format = ImageFormat::Webp;
    if (starts(b, "VP8 ", 12) && b.size() >= 30) {
        if (b[23] != 0x9d || b[24] != 0x01 || b[25] != 0x2a)
            return refused(ImageFormat::Webp, "malformed WebP VP8 header");
        h.width = le16(&b[26]) & 0x3fff;
        h.height = le16(&b[28]) & 0x3fff;
    } else if (starts(b, "VP8L", 12) && b.size() >= 25) {
        if (b[20] != 0x2f) return refused(ImageFormat::Webp, "malformed WebP VP8L header");
        const uint32_t bits = le32(&b[21]);
        h.width = (bits & 0x3fff) + 1;
        h.height = ((bits >> 14) & 0x3fff) + 1;
    } else if (starts(b, "VP8X", 12) && b.size() >= 30) {
        h.width = le24(&b[24]) + 1;
        h.height = le24(&b[27]) + 1;
    } else {
        return refused(ImageFormat::Webp, "truncated or unknown WebP header");
    }
    return h;
}

}  // namespace

ImageHeader read_image_header(const std::vector<uint8_t>& b, bool allow_webp) {
    ImageHeader h;
    if (starts(b, "\x89PNG\r\n\x1a\n"))
        h = png_header(b);
    else if (b.size() >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF)
        h = jpeg_header(b);
    else if (allow_webp && starts(b, "RIFF") && starts(b, "WEBP", 8))
        h = webp_header(b);
    else
        return refused(ImageFormat::Unknown,
                       allow_webp ? "not a PNG, JPEG or WebP image" : "not a PNG or JPEG image");
    if (h.problem.empty() && (h.width == 0 || h.height == 0))
        h.problem = "header claims a " + std::to_string(h.width) + "x" + std::to_string(h.height) +
                    " image";
    return h;
}

const char* image_extension(ImageFormat format) {
    switch (format) {
        case ImageFormat::Png:
            return "png";
        case ImageFormat::Jpeg:
            return "jpg";
        case ImageFormat::Webp:
            return "webp";
        case ImageFormat::Unknown:
            break;
    }
    return "";
}

}  // namespace penumbra
