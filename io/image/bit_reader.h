// A least-significant-bit-first reader over a byte span, as Basis Universal's bitstreams
// are written (BasisLZ codebooks, tables and slices). Reading past the end throws, so a
// truncated or corrupt stream is an error, never an out-of-bounds read.
#pragma once

#include <cstddef>
#include <cstdint>

#include "io/image/ktx2_error.h"

namespace penumbra {

class BitReader {
public:
    BitReader(const uint8_t* data, size_t size) : m_data(data), m_size(size) {}

    // The next n bits (n <= 32), the first read in the lowest bit of the result.
    uint32_t bits(int n) {
        uint32_t v = 0;
        for (int i = 0; i < n; ++i) v |= uint32_t(bit()) << i;
        return v;
    }
    uint32_t bit() {
        if (m_pos >= m_size * 8) throw Ktx2Error("bitstream ends early");
        const uint32_t b = (m_data[m_pos >> 3] >> (m_pos & 7)) & 1u;
        ++m_pos;
        return b;
    }
    // Basis Universal's variable-length integer: chunks of chunk_bits bits, each followed
    // by a bit saying whether another chunk follows; at most 32 bits in all.
    uint32_t vlc(int chunk_bits) {
        uint32_t v = 0;
        for (int shift = 0;; shift += chunk_bits) {
            if (shift >= 32) throw Ktx2Error("variable-length integer is too long");
            const uint32_t s = bits(chunk_bits + 1);
            v |= (s & ((1u << chunk_bits) - 1)) << shift;
            if (!(s >> chunk_bits)) return v;
        }
    }

private:
    const uint8_t* m_data;
    size_t m_size;
    size_t m_pos = 0;
};

}  // namespace penumbra
