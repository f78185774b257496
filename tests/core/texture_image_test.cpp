// TextureImage: texels at their file's precision, the MIP pyramid (box averages in
// linear space, odd sizes by area), the sRGB tables and the bytes it costs.
#include "core/texture_image.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "core/sampling/rng.h"

namespace penumbra {
namespace {

// A float image of w x h x c values from a fixed seed, in [0, 1).
Image random_image(int w, int h, int c, uint64_t seed) {
    Image img(w, h, c);
    Rng rng(seed);
    for (float& v : img.pixels) v = rng.next_float();
    return img;
}

TEST(TextureImage, LevelSizesHalveDownToOne) {
    const TextureImage t(random_image(13, 4, 1, 1));
    ASSERT_EQ(t.levels(), 4);  // 13x4, 6x2, 3x1, 1x1
    const int sizes[4][2] = {{13, 4}, {6, 2}, {3, 1}, {1, 1}};
    for (int l = 0; l < 4; ++l) {
        EXPECT_EQ(t.width(l), sizes[l][0]) << l;
        EXPECT_EQ(t.height(l), sizes[l][1]) << l;
    }
    EXPECT_EQ(TextureImage(random_image(13, 4, 1, 1), false).levels(), 1);
}

// Power-of-two sizes: each texel of level l + 1 is the mean of its 2 x 2 texels.
TEST(TextureImage, MipLevelsAreBoxAverages) {
    const Image src = random_image(16, 8, 3, 2);
    const TextureImage t(src);
    ASSERT_EQ(t.levels(), 5);
    for (int l = 1; l < t.levels(); ++l)
        for (int y = 0; y < t.height(l); ++y)
            for (int x = 0; x < t.width(l); ++x) {
                const int fw = t.width(l - 1), fh = t.height(l - 1);
                Vec4 want;
                int n = 0;
                // A side of 1 stays 1: one texel along it, not two.
                for (int j = 0; j < (fh > 1 ? 2 : 1); ++j)
                    for (int i = 0; i < (fw > 1 ? 2 : 1); ++i) {
                        want = want + t.texel(l - 1, 2 * x + i, 2 * y + j);
                        ++n;
                    }
                want = want * (1.0f / float(n));
                const Vec4 got = t.texel(l, x, y);
                for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1e-6f) << l << " " << x;
            }
    // The top level is the image's mean.
    double mean = 0;
    for (int i = 0; i < 16 * 8; ++i) mean += src.pixels[size_t(3 * i)];
    EXPECT_NEAR(t.texel(t.levels() - 1, 0, 0).x, mean / 128, 1e-6);
}

// Odd sizes: a coarser texel averages the exact area it covers (fractional weights), so
// every level keeps the image's mean, and a texel equals the area integral.
TEST(TextureImage, NonPowerOfTwoPyramidsAverageByArea) {
    const Image src = random_image(5, 3, 1, 3);
    const TextureImage t(src);
    ASSERT_EQ(t.levels(), 3);  // 5x3, 2x1, 1x1
    // Level 1 texel 0 covers x in [0, 2.5), all three rows.
    double want = 0;
    for (int y = 0; y < 3; ++y)
        want += src.pixels[size_t(5 * y)] + src.pixels[size_t(5 * y + 1)] +
                0.5 * src.pixels[size_t(5 * y + 2)];
    EXPECT_NEAR(t.texel(1, 0, 0).x, want / 7.5, 1e-6);
    double mean = 0;
    for (float v : src.pixels) mean += v;
    mean /= 15;
    for (int l = 0; l < t.levels(); ++l) {
        double m = 0;
        for (int y = 0; y < t.height(l); ++y)
            for (int x = 0; x < t.width(l); ++x) m += t.texel(l, x, y).x;
        EXPECT_NEAR(m / (t.width(l) * t.height(l)), mean, 1e-6) << l;
    }
    // 1 x N and N x 1 strips too.
    const TextureImage strip(random_image(1, 7, 1, 4));
    EXPECT_EQ(strip.levels(), 3);  // 1x7, 1x3, 1x1
    EXPECT_EQ(strip.width(2), 1);
}

// sRGB 8-bit: levels are averaged in linear space, then stored as the nearest code. A
// black and white checkerboard's mean is linear 0.5 (code 188), not code 128 (0.216 when
// decoded), which averaging the codes would give.
TEST(TextureImage, SrgbLevelsAverageLinearValues) {
    TextureImage t(2, 2, 3, TexelFormat::U8, true);
    uint8_t* p = static_cast<uint8_t*>(t.level0_data());
    const uint8_t codes[4] = {0, 255, 255, 0};
    for (int i = 0; i < 4; ++i)
        for (int c = 0; c < 3; ++c) p[3 * i + c] = codes[i];
    t.build_mips();
    EXPECT_EQ(t.code(1, 0, 0, 0), 188u);
    EXPECT_NEAR(t.texel(1, 0, 0).x, 0.5f, 0.5f * (srgb8_to_linear(188) - srgb8_to_linear(187)));
    // Texel values are the table's, and alpha is linear.
    TextureImage a(1, 1, 4, TexelFormat::U8, true);
    std::memcpy(a.level0_data(), "\x80\x80\x80\x80", 4);
    EXPECT_EQ(a.texel(0, 0, 0).x, srgb8_to_linear(128));
    EXPECT_FLOAT_EQ(a.texel(0, 0, 0).w, 128.0f / 255);
}

// Every 8-bit code decodes to the sRGB table's value in colour channels and to
// code * (1 / 255) in alpha and non-colour textures, for 1-4 channels; bilinear() is
// the four texels' blend in its documented order, bit for bit, in every format.
TEST(TextureImage, TexelsDecodeAndBilinearBlendsThem) {
    for (const TexelFormat format : {TexelFormat::U8, TexelFormat::U16, TexelFormat::F32})
        for (const bool srgb : {true, false})
            for (int channels = 1; channels <= 4; ++channels) {
                SCOPED_TRACE(std::to_string(int(format)) + " " + std::to_string(srgb) + " " +
                             std::to_string(channels));
                const int w = 256, h = 3;
                TextureImage t(w, h, channels, format, srgb);
                Rng rng(11);
                const size_t n = size_t(w) * h * channels;
                for (size_t i = 0; i < n; ++i) {
                    if (format == TexelFormat::U8)
                        static_cast<uint8_t*>(t.level0_data())[i] = uint8_t(i / channels % 256);
                    else if (format == TexelFormat::U16)
                        static_cast<uint16_t*>(t.level0_data())[i] = uint16_t(rng.next_below(65536));
                    else
                        static_cast<float*>(t.level0_data())[i] = rng.next_float();
                }
                t.build_mips();
                if (format == TexelFormat::U8) {
                    for (int code = 0; code < 256; ++code) {
                        const Vec4 v = t.texel(0, code, 0);
                        const float c0 = srgb ? srgb8_to_linear(uint8_t(code))
                                                : float(code) * (1.0f / 255);
                        ASSERT_EQ(v.x, c0) << code;
                        ASSERT_EQ(v.y, c0) << code;  // gray fill, or the same code
                        ASSERT_EQ(v.z, c0) << code;
                        const float alpha = float(code) * (1.0f / 255);
                        const float want_w = channels == 2 || channels == 4 ? alpha : 1.0f;
                        ASSERT_EQ(v.w, want_w) << code;
                    }
                }
                for (int level = 0; level < t.levels(); ++level)
                    for (int k = 0; k < 50; ++k) {
                        const int lw = t.width(level), lh = t.height(level);
                        const int x0 = int(rng.next_below(uint32_t(lw))),
                                  x1 = int(rng.next_below(uint32_t(lw)));
                        const int y0 = int(rng.next_below(uint32_t(lh))),
                                  y1 = int(rng.next_below(uint32_t(lh)));
                        const float ax = rng.next_float(), ay = rng.next_float();
                        const Vec4 want = t.texel(level, x0, y0) * ((1 - ax) * (1 - ay)) +
                                          t.texel(level, x1, y0) * (ax * (1 - ay)) +
                                          t.texel(level, x0, y1) * ((1 - ax) * ay) +
                                          t.texel(level, x1, y1) * (ax * ay);
                        const Vec4 got = t.bilinear(level, x0, x1, y0, y1, ax, ay);
                        ASSERT_EQ(got.x, want.x);
                        ASSERT_EQ(got.y, want.y);
                        ASSERT_EQ(got.z, want.z);
                        ASSERT_EQ(got.w, want.w);
                    }
            }
}

// 8-bit levels (sRGB and linear, the 2 x 2 fast path and odd sizes' general taps) hold
// the code whose decoded value is nearest the linear box average, found here by
// trying all 256.
TEST(TextureImage, EightBitLevelsHoldTheNearestCode) {
    for (const bool srgb : {true, false})
        for (const int w : {16, 15}) {
            SCOPED_TRACE(std::to_string(srgb) + " " + std::to_string(w));
            TextureImage t(w, 16, 2, TexelFormat::U8, srgb);
            uint8_t* p = static_cast<uint8_t*>(t.level0_data());
            Rng rng(5);
            for (int i = 0; i < w * 16 * 2; ++i) p[i] = uint8_t(rng.next_below(256));
            t.build_mips();
            auto decode = [&](int c, uint32_t code) {
                return srgb && c == 0 ? double(srgb8_to_linear(uint8_t(code))) : code / 255.0;
            };
            const double r = double(w) / t.width(1);  // the finer texels each covers in x
            for (int y = 0; y < t.height(1); ++y)
                for (int x = 0; x < t.width(1); ++x)
                    for (int c = 0; c < 2; ++c) {
                        double sum = 0;
                        for (int j = 0; j < 2; ++j)
                            for (int i = 0; i < w; ++i) {
                                const double lo = std::max(double(i), x * r);
                                const double hi = std::min(double(i + 1), (x + 1) * r);
                                if (hi > lo)
                                    sum += (hi - lo) * decode(c, t.code(0, i, 2 * y + j, c));
                            }
                        const double mean = sum / (2 * r);
                        uint32_t best = 0;
                        for (uint32_t k = 1; k < 256; ++k)
                            if (std::abs(decode(c, k) - mean) < std::abs(decode(c, best) - mean))
                                best = k;
                        // Ties (a linear mean of k + 1/2 codes) may go either way.
                        const uint32_t got = t.code(1, x, y, c);
                        EXPECT_LE(std::abs(decode(c, got) - mean),
                                  std::abs(decode(c, best) - mean) + 1e-6)
                            << x << " " << y << " " << c << ": " << got << " for " << best;
                    }
        }
}

// The table is the IEC 61966-2-1 curve (to OCIO's continuous toe, 2.5e-4 relative, below
// code 11): its two segments, the end points, monotone. io/ checks it against OCIO.
TEST(TextureImage, SrgbTablesFollowTheStandard) {
    EXPECT_EQ(srgb8_to_linear(0), 0.0f);
    EXPECT_EQ(srgb8_to_linear(255), 1.0f);
    EXPECT_EQ(srgb16_to_linear(65535), 1.0f);
    EXPECT_NEAR(srgb8_to_linear(10), 10.0 / 255 / 12.92, 2.5e-4 * 10.0 / 255 / 12.92);
    EXPECT_NEAR(srgb8_to_linear(200), std::pow((200.0 / 255 + 0.055) / 1.055, 2.4), 1e-7);
    for (int i = 1; i < 256; ++i)
        EXPECT_LT(srgb8_to_linear(uint8_t(i - 1)), srgb8_to_linear(uint8_t(i)));
    EXPECT_NEAR(srgb16_to_linear(257 * 200), srgb8_to_linear(200), 1e-7);
}

// 16-bit texels keep neighbouring codes apart (8-bit storage would merge them), at
// level 0 and, averaged, at level 1.
TEST(TextureImage, SixteenBitPrecisionKept) {
    TextureImage t(2, 1, 1, TexelFormat::U16, false);
    uint16_t* p = static_cast<uint16_t*>(t.level0_data());
    p[0] = 30000;
    p[1] = 30002;
    t.build_mips();
    EXPECT_EQ(t.format(), TexelFormat::U16);
    EXPECT_EQ(t.code(0, 1, 0, 0), 30002u);
    EXPECT_FLOAT_EQ(t.texel(0, 0, 0).x, 30000.0f / 65535);
    EXPECT_EQ(t.code(1, 0, 0, 0), 30001u);
    EXPECT_EQ(t.bytes(), 3 * sizeof(uint16_t));
}

// The store's bytes, pyramid included: RGBA8 4 x 4/3 (5.33 per texel), RGB8 4,
// gray 1.33; at most 6 bytes a texel for 8-bit images.
TEST(TextureImage, BytesPerTexelWithThePyramid) {
    const int n = 1024;
    const TextureImage rgba(n, n, 4, TexelFormat::U8, true);
    const double per_texel = double(rgba.bytes()) / double(rgba.texel_count());
    EXPECT_LE(per_texel, 6.0);
    EXPECT_NEAR(per_texel, 4.0 * 4 / 3, 0.01);
    const TextureImage rgb(n, n, 3, TexelFormat::U8, true);
    EXPECT_NEAR(double(rgb.bytes()) / double(rgb.texel_count()), 4.0, 0.01);
    const TextureImage gray(n, n, 1, TexelFormat::U8, false);
    EXPECT_NEAR(double(gray.bytes()) / double(gray.texel_count()), 4.0 / 3, 0.01);
    // Odd sizes have smaller pyramids, never larger.
    const TextureImage odd(1023, 777, 4, TexelFormat::U8, true);
    EXPECT_LE(double(odd.bytes()) / double(odd.texel_count()), 4.0 * 4 / 3);
}

}  // namespace
}  // namespace penumbra
