#include "io/image/basis_huffman.h"

#include <string>

namespace penumbra {

namespace {

constexpr int kMaxCodeLength = 16;
// The code-length code's symbols in the order their 3-bit lengths are sent: the run codes
// (17: 3-10 zeros, 18: 11-138 zeros, 19: 3-6 repeats, 20: 7-134 repeats) first.
constexpr uint8_t kCodeLengthOrder[21] = {17, 18, 19, 20, 0,  8, 7,  9, 6,  10, 5,
                                          11, 4,  12, 3,  13, 2, 14, 1, 15, 16};

}  // namespace

HuffmanTable::HuffmanTable(const std::vector<uint8_t>& lengths)
    : m_symbol_count(uint32_t(lengths.size())) {
    for (uint8_t l : lengths) {
        if (l > kMaxCodeLength) throw Ktx2Error("Huffman code length over 16");
        ++m_count[l];
    }
    m_count[0] = 0;
    // Canonical codes: the codes of each length follow those of the shorter ones. More
    // codes than a length leaves room for is an invalid table.
    int left = 1;
    for (int len = 1; len <= kMaxCodeLength; ++len) {
        left = left * 2 - m_count[len];
        if (left < 0) throw Ktx2Error("over-subscribed Huffman table");
    }
    uint16_t offset[kMaxCodeLength + 2] = {};
    for (int len = 1; len <= kMaxCodeLength; ++len)
        offset[len + 1] = uint16_t(offset[len] + m_count[len]);
    m_sorted.resize(offset[kMaxCodeLength + 1]);
    for (size_t s = 0; s < lengths.size(); ++s)
        if (lengths[s]) m_sorted[offset[lengths[s]]++] = uint16_t(s);
}

uint32_t HuffmanTable::decode(BitReader& in) const {
    if (m_sorted.empty()) throw Ktx2Error("a symbol is coded with an empty Huffman table");
    // The code's first bit is its most significant (Deflate's order): walk the lengths,
    // comparing the code so far with the first code of each.
    int code = 0, first = 0, index = 0;
    for (int len = 1; len <= kMaxCodeLength; ++len) {
        code |= int(in.bit());
        const int count = m_count[len];
        if (code - first < count) return m_sorted[size_t(index + code - first)];
        index += count;
        first = (first + count) << 1;
        code <<= 1;
    }
    throw Ktx2Error("invalid Huffman code");
}

HuffmanTable HuffmanTable::read(BitReader& in) {
    const uint32_t total = in.bits(14);
    if (total == 0) return HuffmanTable();
    const uint32_t n_codes = in.bits(5);
    if (n_codes < 1 || n_codes > 21) throw Ktx2Error("bad Huffman code-length code count");
    std::vector<uint8_t> cl_lengths(21, 0);
    for (uint32_t i = 0; i < n_codes; ++i) cl_lengths[kCodeLengthOrder[i]] = uint8_t(in.bits(3));
    const HuffmanTable cl(cl_lengths);
    std::vector<uint8_t> lengths(total, 0);
    uint32_t cur = 0;
    while (cur < total) {
        const uint32_t c = cl.decode(in);
        uint32_t run = 0;
        uint8_t value = 0;
        if (c <= 16) {
            lengths[cur++] = uint8_t(c);
            continue;
        } else if (c == 17) {
            run = in.bits(3) + 3;
        } else if (c == 18) {
            run = in.bits(7) + 11;
        } else {
            if (cur == 0 || lengths[cur - 1] == 0)
                throw Ktx2Error("Huffman length repeat without a previous length");
            value = lengths[cur - 1];
            run = c == 19 ? in.bits(2) + 3 : in.bits(7) + 7;
        }
        if (run > total - cur) throw Ktx2Error("Huffman length run past the symbol count");
        for (uint32_t i = 0; i < run; ++i) lengths[cur++] = value;
    }
    return HuffmanTable(lengths);
}

}  // namespace penumbra
