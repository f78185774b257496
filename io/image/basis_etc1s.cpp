#include "io/image/basis_etc1s.h"

#include <algorithm>
#include <string>

#include "io/image/ktx2_error.h"

namespace penumbra {

namespace {

uint32_t u32(const uint8_t* p) {
    return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

// ETC1's intensity modifiers, by table and by selector ordered from the most negative.
constexpr int kModifiers[8][4] = {{-8, -2, 2, 8},       {-17, -5, 5, 17},    {-29, -9, 9, 29},
                                  {-42, -13, 13, 42},   {-60, -18, 18, 60},  {-80, -24, 24, 80},
                                  {-106, -33, 33, 106}, {-183, -47, 47, 183}};

// Endpoint prediction: one symbol gives 2 bits for each block of a 2x2 group; symbol 256
// repeats the previous one a VLC-coded number of times.
constexpr uint32_t kPredRepeatSymbol = 256;
constexpr int kPredRepeatVlcBits = 4;
constexpr uint32_t kPredMinRepeat = 3;
// Selector history runs: the symbol after the history entries starts a run of the last
// selector, of 3 + a 6-bit symbol's length (the last symbol: 3 + a 7-bit-chunk VLC).
constexpr uint32_t kRleThreshold = 3, kRleTotal = 64;

// Basis Universal's approximate move-to-front list of recent selector indices: new
// entries go to a rover in the upper half; a used entry swaps with the one at half its
// index.
class SelectorHistory {
public:
    explicit SelectorHistory(uint32_t n) : m_values(n, 0), m_rover(n / 2) {}
    uint32_t size() const { return uint32_t(m_values.size()); }
    uint32_t operator[](uint32_t i) const { return m_values[i]; }
    void add(uint32_t v) {
        m_values[m_rover++] = v;
        if (m_rover == m_values.size()) m_rover = uint32_t(m_values.size() / 2);
    }
    void use(uint32_t i) {
        if (i) std::swap(m_values[i / 2], m_values[i]);
    }

private:
    std::vector<uint32_t> m_values;
    uint32_t m_rover;
};

}  // namespace

BasisLzDecoder::BasisLzDecoder(const uint8_t* sgd, size_t sgd_size, uint32_t image_count) {
    constexpr size_t kHeader = 20, kDesc = 20;
    if (sgd_size < kHeader) throw Ktx2Error("BasisLZ global data is truncated");
    const uint32_t endpoint_count = uint32_t(sgd[0]) | uint32_t(sgd[1]) << 8;
    const uint32_t selector_count = uint32_t(sgd[2]) | uint32_t(sgd[3]) << 8;
    const uint64_t ep_len = u32(sgd + 4), sel_len = u32(sgd + 8), tab_len = u32(sgd + 12),
                   ext_len = u32(sgd + 16);
    const uint64_t need =
        kHeader + kDesc * uint64_t(image_count) + ep_len + sel_len + tab_len + ext_len;
    if (need > sgd_size)
        throw Ktx2Error("BasisLZ global data's lengths add up to " + std::to_string(need) +
                        " bytes, more than its " + std::to_string(sgd_size));
    if (endpoint_count == 0 || selector_count == 0)
        throw Ktx2Error("BasisLZ global data has an empty codebook");
    const uint8_t* p = sgd + kHeader;
    for (uint32_t i = 0; i < image_count; ++i, p += kDesc)
        m_images.push_back({u32(p), u32(p + 4), u32(p + 8), u32(p + 12), u32(p + 16)});
    read_endpoints(p, ep_len, endpoint_count);
    p += ep_len;
    read_selectors(p, sel_len, selector_count);
    p += sel_len;
    read_tables(p, tab_len);
}

// The endpoint codebook: intensity table and 5-bit colour deltas from the previous entry,
// the colour's Huffman table chosen by the previous value's range (0-9, 10-21, 22-31).
void BasisLzDecoder::read_endpoints(const uint8_t* data, size_t size, uint32_t count) {
    BitReader in(data, size);
    const HuffmanTable models[3] = {HuffmanTable::read(in), HuffmanTable::read(in),
                                    HuffmanTable::read(in)};
    const HuffmanTable inten_model = HuffmanTable::read(in);
    const bool grayscale = in.bit() != 0;
    uint32_t prev[3] = {16, 16, 16}, prev_inten = 0;
    m_endpoint_colors.resize(count);
    for (uint32_t i = 0; i < count; ++i) {
        const uint32_t inten = (inten_model.decode(in) + prev_inten) & 7;
        prev_inten = inten;
        uint32_t c5[3];
        for (int c = 0; c < (grayscale ? 1 : 3); ++c) {
            const int model = prev[c] <= 9 ? 0 : prev[c] <= 21 ? 1 : 2;
            c5[c] = prev[c] = (models[model].decode(in) + prev[c]) & 31;
        }
        if (grayscale) c5[1] = c5[2] = c5[0];
        for (int s = 0; s < 4; ++s)
            for (int c = 0; c < 3; ++c) {
                const int base = int((c5[c] << 3) | (c5[c] >> 2));
                m_endpoint_colors[i][size_t(s * 3 + c)] =
                    uint8_t(std::clamp(base + kModifiers[inten][s], 0, 255));
            }
    }
}

// The selector codebook: raw bytes, or the first entry raw and each later row byte XORed
// with the previous entry's through a Huffman table. Global (palette) codebooks belong
// to the old .basis format and are refused.
void BasisLzDecoder::read_selectors(const uint8_t* data, size_t size, uint32_t count) {
    BitReader in(data, size);
    if (in.bit()) throw Ktx2Error("BasisLZ global selector codebooks are not supported");
    if (in.bit()) throw Ktx2Error("BasisLZ hybrid selector codebooks are not supported");
    const bool raw = in.bit() != 0;
    m_selectors.resize(count);
    if (raw) {
        for (auto& s : m_selectors)
            for (auto& row : s) row = uint8_t(in.bits(8));
        return;
    }
    const HuffmanTable delta = HuffmanTable::read(in);
    std::array<uint8_t, 4> prev{};
    for (uint32_t i = 0; i < count; ++i) {
        for (int r = 0; r < 4; ++r)
            prev[size_t(r)] = uint8_t(i == 0 ? in.bits(8) : (delta.decode(in) ^ prev[size_t(r)]));
        m_selectors[i] = prev;
    }
}

void BasisLzDecoder::read_tables(const uint8_t* data, size_t size) {
    BitReader in(data, size);
    m_endpoint_pred = HuffmanTable::read(in);
    m_endpoint_delta = HuffmanTable::read(in);
    m_selector = HuffmanTable::read(in);
    m_selector_rle = HuffmanTable::read(in);
    m_history_size = in.bits(13);
}

template <class Out>
void BasisLzDecoder::decode_slice(const uint8_t* data, size_t size, uint32_t blocks_x,
                                  uint32_t blocks_y, Out out) const {
    BitReader in(data, size);
    const uint32_t n_endpoints = uint32_t(m_endpoint_colors.size());
    const uint32_t n_selectors = uint32_t(m_selectors.size());
    const uint32_t rle_symbol = n_selectors + m_history_size;
    const uint64_t total_blocks = uint64_t(blocks_x) * blocks_y;
    struct Pred {
        uint32_t endpoint = 0, bits = 0;
    };
    // Two rows of prediction state: the row above (endpoints) and the pending odd row.
    std::vector<Pred> rows[2] = {std::vector<Pred>(blocks_x), std::vector<Pred>(blocks_x)};
    SelectorHistory history(m_history_size);
    uint32_t pred_bits = 0, prev_pred_sym = 0, pred_repeat = 0, prev_endpoint = 0, rle = 0;
    for (uint32_t by = 0; by < blocks_y; ++by) {
        std::vector<Pred>& cur = rows[by & 1];
        std::vector<Pred>& other = rows[(by & 1) ^ 1];
        for (uint32_t bx = 0; bx < blocks_x; ++bx) {
            if ((bx & 1) == 0) {
                if ((by & 1) == 0) {
                    if (pred_repeat) {
                        --pred_repeat;
                        pred_bits = prev_pred_sym;
                    } else {
                        const uint32_t sym = m_endpoint_pred.decode(in);
                        if (sym > kPredRepeatSymbol) throw Ktx2Error("bad endpoint predictor");
                        if (sym == kPredRepeatSymbol) {
                            pred_repeat = in.vlc(kPredRepeatVlcBits) + kPredMinRepeat - 1;
                            pred_bits = prev_pred_sym;
                        } else {
                            pred_bits = prev_pred_sym = sym;
                        }
                    }
                    other[bx].bits = pred_bits >> 4;  // the two blocks below these
                } else {
                    pred_bits = cur[bx].bits;
                }
            }
            const uint32_t pred = pred_bits & 3;
            pred_bits >>= 2;
            uint32_t endpoint;
            if (pred == 0) {  // the left block's
                if (bx == 0) throw Ktx2Error("endpoint predicted from the left of the image");
                endpoint = prev_endpoint;
            } else if (pred == 1) {  // the upper block's
                if (by == 0) throw Ktx2Error("endpoint predicted from above the image");
                endpoint = other[bx].endpoint;
            } else if (pred == 2) {  // the upper left block's
                if (bx == 0 || by == 0)
                    throw Ktx2Error("endpoint predicted from outside the image");
                endpoint = other[bx - 1].endpoint;
            } else {  // a delta from the previous block's, modulo the codebook
                endpoint = m_endpoint_delta.decode(in) + prev_endpoint;
                if (endpoint >= n_endpoints) endpoint -= n_endpoints;
                if (endpoint >= n_endpoints) throw Ktx2Error("endpoint index out of range");
            }
            cur[bx].endpoint = prev_endpoint = endpoint;

            uint32_t sym;
            if (rle > 0) {
                --rle;
                sym = n_selectors;
            } else {
                sym = m_selector.decode(in);
                if (sym == rle_symbol) {
                    const uint32_t run = m_selector_rle.decode(in);
                    rle = (run == kRleTotal - 1 ? in.vlc(7) : run) + kRleThreshold;
                    if (rle > total_blocks) throw Ktx2Error("selector run past the slice");
                    sym = n_selectors;
                    --rle;
                } else if (sym > rle_symbol) {
                    throw Ktx2Error("selector symbol out of range");
                }
            }
            uint32_t selector;
            if (sym >= n_selectors) {
                const uint32_t h = sym - n_selectors;
                if (h >= history.size()) throw Ktx2Error("selector history index out of range");
                selector = history[h];
                history.use(h);
            } else {
                selector = sym;
                if (m_history_size) history.add(selector);
            }
            out(bx, by, endpoint, selector);
        }
    }
}

void BasisLzDecoder::decode(uint32_t image, const uint8_t* level, size_t level_size, uint32_t width,
                            uint32_t height, int second, uint8_t* rgba) const {
    if (image >= m_images.size()) throw Ktx2Error("no BasisLZ image descriptor");
    const ImageDesc& d = m_images[image];
    if (d.flags & 2) throw Ktx2Error("BasisLZ P-frames (video) are not supported");
    auto check = [&](uint32_t offset, uint32_t length, const char* what) {
        if (length == 0 || offset > level_size || length > level_size - offset)
            throw Ktx2Error(std::string("BasisLZ ") + what + " slice lies outside its level");
    };
    check(d.rgb_offset, d.rgb_length, "RGB");
    if (second >= 0) check(d.alpha_offset, d.alpha_length, "second");
    const uint32_t bw = (width + 3) / 4, bh = (height + 3) / 4;
    auto pixels = [&](bool alpha_slice) {
        return [&, alpha_slice](uint32_t bx, uint32_t by, uint32_t e, uint32_t s) {
            const uint8_t* colors = m_endpoint_colors[e].data();
            const std::array<uint8_t, 4>& sel = m_selectors[s];
            for (uint32_t y = 0; y < 4 && by * 4 + y < height; ++y)
                for (uint32_t x = 0; x < 4 && bx * 4 + x < width; ++x) {
                    const uint32_t i = (sel[y] >> (2 * x)) & 3;
                    uint8_t* px = rgba + (size_t(by * 4 + y) * width + bx * 4 + x) * 4;
                    if (alpha_slice) {
                        px[second] = colors[i * 3 + 1];  // the slice is grey: take green
                    } else {
                        px[0] = colors[i * 3];
                        px[1] = colors[i * 3 + 1];
                        px[2] = colors[i * 3 + 2];
                        px[3] = 255;
                    }
                }
        };
    };
    decode_slice(level + d.rgb_offset, d.rgb_length, bw, bh, pixels(false));
    if (second >= 0) decode_slice(level + d.alpha_offset, d.alpha_length, bw, bh, pixels(true));
}

}  // namespace penumbra
