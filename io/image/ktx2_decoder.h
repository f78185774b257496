// KTX2 textures with Basis Universal payloads (glTF's KHR_texture_basisu) decoded into
// the texture system's 8-bit storage, with the mip levels the file carries.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/texture_image.h"

namespace penumbra {

// Decodes a KTX2 file of BasisLZ/ETC1S or UASTC data (UASTC optionally Zstandard-
// supercompressed) to 8-bit RGB, or RGBA when the file has alpha. The transfer function
// is the file's (its DFD's sRGB or linear), the orientation is turned to top-left first
// (KTXorientation), and KTXswizzle is applied. With `mipmaps`, the file's levels fill the
// pyramid and build_mips() makes the ones it lacks; without, level 0 alone. Throws
// ImageDecodeError naming `name` on anything invalid or unsupported, before allocating
// more than max_pixels texels (and their pyramid).
TextureImage decode_ktx2(const std::vector<uint8_t>& bytes, const std::string& name,
                         uint64_t max_pixels, bool mipmaps = true);

}  // namespace penumbra
