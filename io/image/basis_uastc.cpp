#include "io/image/basis_uastc.h"

#include <string>

#include "io/image/basis_uastc_tables.h"
#include "io/image/ktx2_error.h"

namespace penumbra {

namespace {

using uastc::BiseRange;
using uastc::Layout;
using uastc::Mode;

// The block's bits, least significant first, as two 64-bit words; every mode's fields
// fit in the 128 bits (the tables are fixed), and reads past them give zeros.
class BlockBits {
public:
    explicit BlockBits(const uint8_t* b) {
        for (int i = 7; i >= 0; --i) {
            m_lo = (m_lo << 8) | b[i];
            m_hi = (m_hi << 8) | b[i + 8];
        }
    }
    uint32_t read(int n) {  // n <= 32
        if (n == 0) return 0;
        uint64_t v = 0;
        if (m_pos >= 128)
            v = 0;
        else if (m_pos >= 64)
            v = m_hi >> (m_pos - 64);
        else if (m_pos == 0)
            v = m_lo;
        else
            v = (m_lo >> m_pos) | (m_hi << (64 - m_pos));
        m_pos += n;
        return uint32_t(v & ((uint64_t(1) << n) - 1));
    }
    void skip(int n) { m_pos += n; }

private:
    uint64_t m_lo = 0, m_hi = 0;
    int m_pos = 0;
};

// UASTC's BISE: the trits (5 to 8 bits) or quints (3 to 7 bits) of all values packed
// first as base-3 or base-5 numbers, then each value's plain bits; values come out
// unquantised to 0-255 with ASTC's colour unquantisation.
void read_endpoints(BlockBits& in, const BiseRange& r, int count, uint8_t* out) {
    uint8_t tq[18] = {};
    if (r.trits || r.quints) {
        const int group = r.trits ? 5 : 3, base = r.trits ? 3 : 5;
        // Bits for the last group of 1..group values: ceil(log2(base^n)).
        static constexpr int kTritBits[6] = {0, 2, 4, 5, 7, 8};
        static constexpr int kQuintBits[4] = {0, 3, 5, 7};
        for (int first = 0; first < count; first += group) {
            const int n = count - first < group ? count - first : group;
            uint32_t packed = in.read(r.trits ? kTritBits[n] : kQuintBits[n]);
            for (int i = 0; i < n; ++i, packed /= uint32_t(base))
                tq[first + i] = uint8_t(packed % uint32_t(base));
        }
    }
    for (int i = 0; i < count; ++i) {
        const uint32_t bits = in.read(r.bits);
        if (!r.trits && !r.quints) {
            // Plain bits: replicated from the top down to fill 8 bits.
            uint32_t v = 0;
            for (int shift = 8 - r.bits; shift > -r.bits; shift -= r.bits)
                v |= shift >= 0 ? bits << shift : bits >> -shift;
            out[i] = uint8_t(v);
            continue;
        }
        // ASTC's unquantisation (ASTC specification, "Color Endpoint Unquantization"):
        // T = D * C + B, flipped by A (the low bit replicated), top bit from A.
        const uint32_t a = (bits & 1) ? 0x1FF : 0;
        uint32_t b = 0;
        for (int j = 0; j < 9; ++j) {
            b <<= 1;
            const char c = r.b[j];
            if (c != '0') b |= (bits >> (c - 'a')) & 1;
        }
        const uint32_t t = (uint32_t(tq[i]) * r.c + b) ^ a;
        out[i] = uint8_t((a & 0x80) | (t >> 2));
    }
}

// ASTC's weight unquantisation for plain-bit ranges: replicated to 6 bits, and values
// above 32 moved up by one so that the top code is 64.
uint32_t unquantise_weight(uint32_t w, int bits) {
    uint32_t v = 0;
    for (int shift = 6 - bits; shift > -bits; shift -= bits)
        v |= shift >= 0 ? w << shift : w >> -shift;
    return v > 32 ? v + 1 : v;
}

// ASTC LDR interpolation of 8-bit endpoints expanded to 16 bits (linear, not sRGB: the
// texture system decodes the transfer function afterwards), back to 8 bits.
uint8_t interpolate(uint32_t l, uint32_t h, uint32_t w) {
    l = (l << 8) | l;
    h = (h << 8) | h;
    return uint8_t(((l * (64 - w) + h * w + 32) >> 6) >> 8);
}

// The subset of each texel and the anchor texel of each subset.
void partition(const Mode& m, int mode_index, BlockBits& in, const uint8_t** subsets,
               const uint8_t** anchors) {
    static const uint8_t kSingle[16] = {}, kSingleAnchor[1] = {0};
    *subsets = kSingle;
    *anchors = kSingleAnchor;
    if (m.subsets == 1) return;
    const uint32_t p = in.read(m.subsets == 3 ? 4 : 5);
    const int limit = mode_index == 7  ? uastc::kPatterns7
                      : m.subsets == 3 ? uastc::kPatterns3
                                       : uastc::kPatterns2;
    if (p >= uint32_t(limit))
        throw Ktx2Error("UASTC block (mode " + std::to_string(mode_index) + ") has pattern " +
                        std::to_string(p) + " of " + std::to_string(limit));
    if (mode_index == 7) {
        *subsets = uastc::kPattern7[p];
        *anchors = uastc::kAnchor7[p];
    } else if (m.subsets == 3) {
        *subsets = uastc::kPattern3[p];
        *anchors = uastc::kAnchor3[p];
    } else {
        *subsets = uastc::kPattern2[p];
        *anchors = uastc::kAnchor2[p];
    }
}

}  // namespace

void decode_uastc_block(const uint8_t block[16], uint8_t rgba[64]) {
    const int mode_index = uastc::kModeOfPrefix[block[0] & 0x7F];
    if (mode_index >= 19) throw Ktx2Error("UASTC block uses the reserved mode");
    const Mode& m = uastc::kModes[mode_index];
    BlockBits in(block);
    in.skip(m.prefix_bits);
    if (mode_index == 8) {  // solid colour
        uint8_t c[4];
        for (uint8_t& v : c) v = uint8_t(in.read(8));
        for (int i = 0; i < 16; ++i)
            for (int k = 0; k < 4; ++k) rgba[i * 4 + k] = c[k];
        return;
    }
    in.skip(m.hint_bits);
    int plane1_component = -1;  // the component the second weight plane drives
    if (m.planes == 2) plane1_component = m.layout == Layout::La ? 3 : int(in.read(2));
    const uint8_t *subset_of, *anchors;
    partition(m, mode_index, in, &subset_of, &anchors);

    const int channels = m.layout == Layout::Rgb ? 3 : m.layout == Layout::Rgba ? 4 : 2;
    uint8_t ep[18];
    read_endpoints(in, uastc::kBise[m.endpoint_range], channels * 2 * m.subsets, ep);

    uint8_t weights[32];
    for (int t = 0; t < 16; ++t) {
        bool anchor = false;
        for (int s = 0; s < m.subsets; ++s) anchor |= anchors[s] == t;
        const int bits = m.weight_bits - (anchor ? 1 : 0);
        for (int p = 0; p < m.planes; ++p)
            weights[t * m.planes + p] = uint8_t(unquantise_weight(in.read(bits), m.weight_bits));
    }

    for (int t = 0; t < 16; ++t) {
        const uint8_t* e = ep + subset_of[t] * channels * 2;
        // Endpoint pairs (low, high) per channel: RGB(A) as stored, LA's L fills RGB.
        uint32_t lo[4], hi[4];
        for (int k = 0; k < 4; ++k) {
            const int src = m.layout == Layout::La ? (k < 3 ? 0 : 1) : k;
            if (src < channels) {
                lo[k] = e[2 * src];
                hi[k] = e[2 * src + 1];
            } else {
                lo[k] = hi[k] = 255;
            }
        }
        for (int k = 0; k < 4; ++k) {
            const int plane = k == plane1_component ? 1 : 0;
            rgba[t * 4 + k] = interpolate(lo[k], hi[k], weights[t * m.planes + plane]);
        }
    }
}

}  // namespace penumbra
