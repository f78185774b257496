// Decoding images (files or bytes in memory, any format OpenImageIO reads) into linear
// float Images. Colour data stored with the sRGB transfer is converted on request (by
// io/color.h, the one definition of the sRGB curve).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/image.h"

namespace penumbra {

enum class ImageEncoding { Linear, Srgb };

// Throws SceneError naming `name` when the data cannot be decoded.
Image decode_image(const std::vector<uint8_t>& bytes, const std::string& name,
                   ImageEncoding encoding);
Image read_image(const std::string& path, ImageEncoding encoding);

}  // namespace penumbra
