#include "core/texture_image.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "core/error.h"

namespace penumbra {

namespace {

double srgb_decode(double v) {
    // IEC 61966-2-1's 2.4 power segment with offset 0.055, joined to the linear toe with
    // a continuous slope (1 / 12.923 rather than the standard's rounded 1 / 12.92), as
    // the built-in OCIO config's sRGB space evaluates it (OCIO's MonCurve), so textures
    // decode as io/color/color.h does (docs/conventions.md: one definition of the curve).
    constexpr double g = 2.4, o = 0.055, brk = o / (g - 1);
    static const double slope = g / (1 + o) * std::pow(o * g / ((g - 1) * (1 + o)), g - 1);
    return v <= brk ? v * slope : std::pow((v + o) / (1 + o), g);
}

// Decoded values of every code, and the midpoints between neighbours in linear space:
// encoding a linear value is a search among the midpoints, giving the code whose
// decoded value is nearest (so a re-encoded mip texel is the best the format holds).
struct SrgbTable {
    std::vector<float> decoded, midpoints;
    // 8-bit only: the code at the start of each of kBuckets equal steps of [0, 1], from
    // which encode() walks a step or two (the curve's steepest part, at 0, spans 0.8
    // codes a bucket) instead of searching all the midpoints.
    static constexpr int kBuckets = 4096;
    std::vector<uint16_t> bucket;
    explicit SrgbTable(uint32_t max_code) : decoded(max_code + 1), midpoints(max_code) {
        for (uint32_t i = 0; i <= max_code; ++i)
            decoded[i] = float(srgb_decode(double(i) / max_code));
        for (uint32_t i = 0; i < max_code; ++i)
            midpoints[i] = float(0.5 * (double(decoded[i]) + decoded[i + 1]));
        if (max_code == 255)
            for (int k = 0; k <= kBuckets; ++k)
                bucket.push_back(uint16_t(search(float(k) / kBuckets)));
    }
    uint32_t search(float v) const {
        return uint32_t(std::upper_bound(midpoints.begin(), midpoints.end(), v) -
                        midpoints.begin());
    }
    uint32_t encode(float v) const {
        if (bucket.empty() || !(v > 0) || !(v < 1)) return search(v);
        uint32_t c = bucket[size_t(v * kBuckets)];
        // The same answer as search(v): up past midpoints below v, down past those above.
        while (c < midpoints.size() && v >= midpoints[c]) ++c;
        while (c > 0 && v < midpoints[c - 1]) --c;
        return c;
    }
};

const SrgbTable& srgb8_table() {
    static const SrgbTable t(255);
    return t;
}
// code * (1 / 255) for every 8-bit code, as linear() decodes non-colour channels.
const float* unorm8_table() {
    static const std::array<float, 256> t = [] {
        std::array<float, 256> v{};
        for (int i = 0; i < 256; ++i) v[size_t(i)] = float(i) * (1.0f / 255);
        return v;
    }();
    return t.data();
}

const SrgbTable& srgb16_table() {
    static const SrgbTable t(65535);
    return t;
}

// The finer-level texels that one coarser texel covers along an axis, with the share of
// its width each covers: output i spans [i n / m, (i + 1) n / m) of the n finer texels.
struct Taps {
    int first = 0, count = 0;
    float weight[4] = {0, 0, 0, 0};
};

Taps axis_taps(int i, int n, int m) {
    Taps t;
    const double lo = double(i) * n / m, hi = double(i + 1) * n / m;
    t.first = int(std::floor(lo));
    const int last = std::min(n, int(std::ceil(hi)));
    t.count = last - t.first;
    CHECK(t.count >= 1 && t.count <= 4);
    for (int k = 0; k < t.count; ++k) {
        const double a = std::max(lo, double(t.first + k)),
                     b = std::min(hi, double(t.first + k + 1));
        t.weight[k] = float((b - a) / (hi - lo));
    }
    return t;
}

// The common case, 8-bit halved exactly (src 2w x 2h, dst w x h, C channels): each
// texel the mean of its 2 x 2, through per-channel decode tables (several times faster
// than the general taps).
void downsample_u8_2x2(const uint8_t* src, uint8_t* dst, int w, int h, int C, bool srgb_colour) {
    const SrgbTable& srgb = srgb8_table();
    float lut[4][256];
    bool colour[4];
    for (int c = 0; c < C; ++c) {
        colour[c] = srgb_colour && !((C == 2 && c == 1) || (C == 4 && c == 3));
        for (int i = 0; i < 256; ++i)
            lut[c][i] = colour[c] ? srgb.decoded[size_t(i)] : float(i) / 255;
    }
    const size_t row = size_t(2 * w) * size_t(C);
    tbb::parallel_for(tbb::blocked_range<int>(0, h), [&](const tbb::blocked_range<int>& rows) {
        for (int y = rows.begin(); y < rows.end(); ++y) {
            const uint8_t* a = src + size_t(2 * y) * row;
            const uint8_t* b = a + row;
            uint8_t* out = dst + size_t(y) * size_t(w) * size_t(C);
            for (int x = 0; x < w; ++x, a += 2 * C, b += 2 * C, out += C)
                for (int c = 0; c < C; ++c) {
                    const float v =
                        0.25f * (lut[c][a[c]] + lut[c][a[C + c]] + lut[c][b[c]] + lut[c][b[C + c]]);
                    out[c] = uint8_t(colour[c] ? srgb.encode(v) : uint32_t(std::lround(v * 255)));
                }
        }
    });
}

}  // namespace

float srgb8_to_linear(uint8_t code) { return srgb8_table().decoded[code]; }
float srgb16_to_linear(uint16_t code) { return srgb16_table().decoded[code]; }

TextureImage::TextureImage(int width, int height, int channels, TexelFormat format, bool srgb,
                           bool mipmaps)
    : m_channels(channels), m_format(format), m_srgb(srgb && format != TexelFormat::F32) {
    CHECK(width > 0 && height > 0 && channels >= 1 && channels <= 4);
    size_t total = 0;
    int w = width, h = height;
    for (;;) {
        m_levels.push_back({w, h, total});
        total += size_t(w) * size_t(h) * size_t(channels);
        if (!mipmaps || (w == 1 && h == 1)) break;
        w = std::max(1, w / 2);
        h = std::max(1, h / 2);
    }
    switch (format) {
        case TexelFormat::U8:
            m_u8.resize(total);
            for (int c = 0; c < channels; ++c) {
                const bool colour = m_srgb && !((channels == 2 && c == 1) || (channels == 4 && c == 3));
                m_u8_lut[c] = colour ? srgb8_table().decoded.data() : unorm8_table();
            }
            break;
        case TexelFormat::U16:
            m_u16.resize(total);
            break;
        case TexelFormat::F32:
            m_f32.resize(total);
            break;
    }
}

TextureImage::TextureImage(const Image& image, bool mipmaps)
    : TextureImage(image.width, image.height, image.channels, TexelFormat::F32, false, mipmaps) {
    name = image.name;
    std::copy(image.pixels.begin(), image.pixels.end(), m_f32.begin());
    build_mips();
}

void* TextureImage::level0_data() {
    switch (m_format) {
        case TexelFormat::U8:
            return m_u8.data();
        case TexelFormat::U16:
            return m_u16.data();
        default:
            return m_f32.data();
    }
}

void* TextureImage::level_data(int level) {
    const size_t first = m_levels[size_t(level)].offset;
    switch (m_format) {
        case TexelFormat::U8:
            return m_u8.data() + first;
        case TexelFormat::U16:
            return m_u16.data() + first;
        default:
            return m_f32.data() + first;
    }
}

float TextureImage::linear(size_t i, int c) const {
    // Alpha is linear in every encoding (glTF 2.0, section 3.9.2).
    const bool colour = m_srgb && !((m_channels == 2 && c == 1) || (m_channels == 4 && c == 3));
    switch (m_format) {
        case TexelFormat::U8:
            return colour ? srgb8_table().decoded[m_u8[i]] : float(m_u8[i]) * (1.0f / 255);
        case TexelFormat::U16:
            return colour ? srgb16_table().decoded[m_u16[i]] : float(m_u16[i]) * (1.0f / 65535);
        default:
            return m_f32[i];
    }
}

void TextureImage::store(size_t i, int c, float v) {
    const bool colour = m_srgb && !((m_channels == 2 && c == 1) || (m_channels == 4 && c == 3));
    switch (m_format) {
        case TexelFormat::U8:
            m_u8[i] = uint8_t(colour ? srgb8_table().encode(v)
                                     : std::lround(std::clamp(v, 0.0f, 1.0f) * 255));
            break;
        case TexelFormat::U16:
            m_u16[i] = uint16_t(colour ? srgb16_table().encode(v)
                                       : std::lround(std::clamp(v, 0.0f, 1.0f) * 65535));
            break;
        default:
            m_f32[i] = v;
    }
}

void TextureImage::downsample(int level) {
    const int fw = width(level - 1), fh = height(level - 1);
    const int w = width(level), h = height(level);
    if (m_format == TexelFormat::U8 && fw == 2 * w && fh == 2 * h)
        return downsample_u8_2x2(&m_u8[index(level - 1, 0, 0)], &m_u8[index(level, 0, 0)], w, h,
                                 m_channels, m_srgb);
    std::vector<Taps> tx(size_t(w), Taps{});
    for (int x = 0; x < w; ++x) tx[size_t(x)] = axis_taps(x, fw, w);
    tbb::parallel_for(tbb::blocked_range<int>(0, h), [&](const tbb::blocked_range<int>& rows) {
        for (int y = rows.begin(); y < rows.end(); ++y) {
            const Taps ty = axis_taps(y, fh, h);
            for (int x = 0; x < w; ++x) {
                const Taps& t = tx[size_t(x)];
                float sum[4] = {0, 0, 0, 0};
                for (int j = 0; j < ty.count; ++j)
                    for (int k = 0; k < t.count; ++k) {
                        const float wt = ty.weight[j] * t.weight[k];
                        const size_t src = index(level - 1, t.first + k, ty.first + j);
                        for (int c = 0; c < m_channels; ++c)
                            sum[c] += wt * linear(src + size_t(c), c);
                    }
                const size_t dst = index(level, x, y);
                for (int c = 0; c < m_channels; ++c) store(dst + size_t(c), c, sum[c]);
            }
        }
    });
}

void TextureImage::build_mips(int first_level) {
    for (int level = std::max(1, first_level); level < levels(); ++level) downsample(level);
}

Vec4 TextureImage::texel_u8(size_t i) const {
    const uint8_t* p = &m_u8[i];
    switch (m_channels) {
        case 1: {
            const float g = m_u8_lut[0][p[0]];
            return {g, g, g, 1};
        }
        case 2: {
            const float g = m_u8_lut[0][p[0]];
            return {g, g, g, m_u8_lut[1][p[1]]};
        }
        case 3:
            return {m_u8_lut[0][p[0]], m_u8_lut[1][p[1]], m_u8_lut[2][p[2]], 1};
        default:
            return {m_u8_lut[0][p[0]], m_u8_lut[1][p[1]], m_u8_lut[2][p[2]], m_u8_lut[3][p[3]]};
    }
}

Vec4 TextureImage::bilinear(int level, int x0, int x1, int y0, int y1, float ax, float ay) const {
    const Level& l = m_levels[size_t(level)];
    const size_t c = size_t(m_channels), row0 = size_t(y0) * size_t(l.width),
                 row1 = size_t(y1) * size_t(l.width);
    const size_t i00 = l.offset + (row0 + size_t(x0)) * c, i10 = l.offset + (row0 + size_t(x1)) * c;
    const size_t i01 = l.offset + (row1 + size_t(x0)) * c, i11 = l.offset + (row1 + size_t(x1)) * c;
    if (m_format == TexelFormat::U8)
        return texel_u8(i00) * ((1 - ax) * (1 - ay)) + texel_u8(i10) * (ax * (1 - ay)) +
               texel_u8(i01) * ((1 - ax) * ay) + texel_u8(i11) * (ax * ay);
    return texel(level, x0, y0) * ((1 - ax) * (1 - ay)) + texel(level, x1, y0) * (ax * (1 - ay)) +
           texel(level, x0, y1) * ((1 - ax) * ay) + texel(level, x1, y1) * (ax * ay);
}

Vec4 TextureImage::texel(int level, int x, int y) const {
    const size_t i = index(level, x, y);
    if (m_format == TexelFormat::U8) return texel_u8(i);
    switch (m_channels) {
        case 1: {
            const float g = linear(i, 0);
            return {g, g, g, 1};
        }
        case 2: {
            const float g = linear(i, 0);
            return {g, g, g, linear(i + 1, 1)};
        }
        case 3:
            return {linear(i, 0), linear(i + 1, 1), linear(i + 2, 2), 1};
        default:
            return {linear(i, 0), linear(i + 1, 1), linear(i + 2, 2), linear(i + 3, 3)};
    }
}

Image TextureImage::to_image(int level) const {
    Image out(width(level), height(level), m_channels);
    out.name = name;
    const size_t n = size_t(out.width) * size_t(out.height) * size_t(m_channels);
    const size_t first = index(level, 0, 0);
    for (size_t i = 0; i < n; ++i) out.pixels[i] = linear(first + i, int(i % size_t(m_channels)));
    return out;
}

uint32_t TextureImage::code(int level, int x, int y, int c) const {
    const size_t i = index(level, x, y) + size_t(c);
    switch (m_format) {
        case TexelFormat::U8:
            return m_u8[i];
        case TexelFormat::U16:
            return m_u16[i];
        default:
            return 0;
    }
}

size_t TextureImage::bytes() const {
    return m_u8.size() + m_u16.size() * sizeof(uint16_t) + m_f32.size() * sizeof(float);
}

}  // namespace penumbra
