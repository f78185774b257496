// Basis Universal's canonical Huffman codes (the BasisLZ codebooks and slices): a table
// is sent as code lengths, themselves coded with a small code-length code and zero and
// repeat runs, as in Deflate. Tables are validated when read (no over-subscribed code, no
// run past the symbol count), so decoding never indexes outside them.
#pragma once

#include <cstdint>
#include <vector>

#include "io/image/bit_reader.h"

namespace penumbra {

class HuffmanTable {
public:
    HuffmanTable() = default;
    // From one code length per symbol (0: unused), each at most 16. Throws on a code
    // with more codes of some length than the lengths allow.
    explicit HuffmanTable(const std::vector<uint8_t>& lengths);
    // Reads a table as BasisLZ writes it (14-bit symbol count, code-length code, runs).
    static HuffmanTable read(BitReader& in);

    // The next symbol; throws when the bits match no code or the table is empty.
    uint32_t decode(BitReader& in) const;
    uint32_t symbol_count() const { return m_symbol_count; }
    bool empty() const { return m_sorted.empty(); }

private:
    uint16_t m_count[17] = {};       // codes of each length
    std::vector<uint16_t> m_sorted;  // used symbols by (length, symbol)
    uint32_t m_symbol_count = 0;
};

}  // namespace penumbra
