// UASTC, Basis Universal's 4x4-block LDR format (the UASTC Texture Specification): each
// 128-bit block is one of 19 modes, ASTC-like (BISE-coded endpoints, 1-3 subsets from
// fixed partition tables, one or two weight planes) plus transcoding hints, which a
// decoder to RGBA skips. Decoded straight to 8-bit RGBA as an ASTC LDR decoder would.
#pragma once

#include <cstdint>

namespace penumbra {

// Decodes one 16-byte block into 16 RGBA texels (row-major, 64 bytes). Throws Ktx2Error
// on the reserved mode or a partition pattern outside the tables.
void decode_uastc_block(const uint8_t block[16], uint8_t rgba[64]);

}  // namespace penumbra
