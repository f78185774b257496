// Decoding images (files or bytes in memory): glTF textures into TextureImages at their
// own precision (sRGB decoded at lookup), other images into linear float Images (sRGB
// converted by io/color/color.h). glTF images are held to the formats glTF allows, by their bytes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/image.h"
#include "core/texture_image.h"

namespace penumbra {

enum class ImageEncoding { Linear, Srgb };

// 2^28 pixels (16k x 16k): 1.3 GiB as RGBA8 with its pyramid (4 GiB as float RGBA), more
// than any texture a renderer on one machine should take on without being asked.
constexpr uint64_t kDefaultMaxTexturePixels = uint64_t(1) << 28;

// A SceneError "<name>: cannot decode image: <why>" that keeps `why` apart, for callers
// that phrase their own message (e.g. a glTF warning).
class ImageDecodeError : public SceneError {
public:
    ImageDecodeError(const std::string& name, const std::string& why)
        : SceneError(name + ": cannot decode image: " + why), m_why(why) {}
    const std::string& why() const { return m_why; }

private:
    std::string m_why;
};

// What a glTF image may be: PNG or JPEG, WebP only where EXT_texture_webp allows it, KTX2
// (Basis Universal, io/image/ktx2_decoder.h) only where KHR_texture_basisu does, and
// at most max_pixels pixels as its header claims.
struct TextureDecodeLimits {
    bool allow_webp = false;
    bool allow_ktx2 = false;  // KHR_texture_basisu is used: KTX2 images are glTF images
    uint64_t max_pixels = kDefaultMaxTexturePixels;
};

// A glTF image's bytes: the format from their signature (never the name or OIIO's
// guess) and the size from their header, checked before decoding; 8-bit and 16-bit
// files stay so, with the MIP pyramid unless mipmaps is false. Throws ImageDecodeError
// naming `name`. (OIIO's TextureSystem is not used: it reads files through its own
// cache, and glTF images are mostly bytes in buffers or data URIs.)
TextureImage decode_texture_image(const std::vector<uint8_t>& bytes, const std::string& name,
                                  ImageEncoding encoding, const TextureDecodeLimits& limits,
                                  bool mipmaps = true);

// Any format OpenImageIO reads (the user's own files, e.g. an EXR environment map), by
// signature or else the name's extension. Throws ImageDecodeError naming `name`.
Image decode_image(const std::vector<uint8_t>& bytes, const std::string& name,
                   ImageEncoding encoding);
Image read_image(const std::string& path, ImageEncoding encoding);

}  // namespace penumbra
