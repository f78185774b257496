// The formats a glTF image may have (PNG, JPEG; WebP under EXT_texture_webp), recognised
// by their signature bytes, and the dimensions their headers claim, read before any
// decoder sees the data so that a hostile header cannot make us allocate.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace penumbra {

enum class ImageFormat { Unknown, Png, Jpeg, Webp };

struct ImageHeader {
    ImageFormat format = ImageFormat::Unknown;
    uint32_t width = 0, height = 0;
    std::string problem;  // non-empty: the bytes are refused, and why
};

// The format and dimensions in the header of `bytes`. A signature other than PNG or
// JPEG (or WebP when `allow_webp`), a truncated or malformed header, or a zero width or
// height sets `problem`.
ImageHeader read_image_header(const std::vector<uint8_t>& bytes, bool allow_webp);

// The file extension OIIO knows the format by ("png", "jpg", "webp").
const char* image_extension(ImageFormat format);

}  // namespace penumbra
