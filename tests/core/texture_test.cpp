// Texture lookups: the level of detail from a footprint, trilinear filtering, glTF's
// filters (NEAREST stays nearest, minFilter without mipmaps reads level 0), wrap modes at
// every level, and what filtering buys: a minified checkerboard's variance.
#include "core/texture.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/sampling/rng.h"

namespace penumbra {
namespace {

// An 8 x 8 gray image of random texels (so are its levels' texels), so a wrong texel
// shows.
TextureImage ramp() {
    Image img(8, 8, 1);
    Rng rng(11);
    for (float& v : img.pixels) v = rng.next_float();
    return TextureImage(img);
}

// The footprint width whose level of detail is exactly `lod` on a w x w texture.
float width_for(float lod, int w) { return std::exp2(lod) / float(w); }

TEST(Texture, LevelOfDetailFromTheFootprint) {
    const TextureImage t = ramp();
    EXPECT_EQ(texture_lod(t, 0), -std::numeric_limits<float>::infinity());
    EXPECT_FLOAT_EQ(texture_lod(t, 1.0f / 8), 0);
    EXPECT_FLOAT_EQ(texture_lod(t, 4.0f / 8), 2);
}

// Width 0 is a point: bilinear at level 0, the lookup without a footprint.
TEST(Texture, ZeroWidthIsBilinearAtLevelZero) {
    const TextureImage t = ramp();
    const Texture tex;
    const Vec2 uv(0.3f, 0.71f);
    const float x = uv.x * 8 - 0.5f, y = uv.y * 8 - 0.5f;
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    const float ax = x - float(x0), ay = y - float(y0);
    const float want =
        t.texel(0, x0, y0).x * (1 - ax) * (1 - ay) + t.texel(0, x0 + 1, y0).x * ax * (1 - ay) +
        t.texel(0, x0, y0 + 1).x * (1 - ax) * ay + t.texel(0, x0 + 1, y0 + 1).x * ax * ay;
    EXPECT_NEAR(lookup(tex, t, uv).x, want, 1e-6f);
    // Texel centres read the texel exactly.
    EXPECT_EQ(lookup(tex, t, {2.5f / 8, 5.5f / 8}).x, t.texel(0, 2, 5).x);
}

// Between two levels the result is their blend by the fractional level.
TEST(Texture, TrilinearBlendsNeighbouringLevels) {
    const TextureImage t = ramp();
    const Texture tex;
    const Vec2 uv(0.4f, 0.6f);
    Texture one_level = tex;
    one_level.mip = MipFilter::Nearest;
    const float l1 = lookup(one_level, t, uv, width_for(1, 8)).x;
    const float l2 = lookup(one_level, t, uv, width_for(2, 8)).x;
    EXPECT_NEAR(lookup(tex, t, uv, width_for(1.25f, 8)).x, 0.75f * l1 + 0.25f * l2, 1e-6f);
    EXPECT_NE(l1, l2);
    // Past the top level: the 1 x 1 mean.
    EXPECT_NEAR(lookup(tex, t, uv, 100).x, t.texel(t.levels() - 1, 0, 0).x, 1e-6f);
}

// NEAREST magnification returns texels unblended; minFilter NEAREST / LINEAR (no
// mipmaps) reads level 0 however wide the footprint; *_MIPMAP_NEAREST one level.
TEST(Texture, SamplerFiltersHonoured) {
    const TextureImage t = ramp();
    Texture nearest;
    nearest.nearest = true;
    const Vec2 uv(0.3f, 0.71f);  // texel (2, 5), off its centre
    EXPECT_EQ(lookup(nearest, t, uv).x, t.texel(0, 2, 5).x);
    EXPECT_EQ(lookup(nearest, t, uv, width_for(-1, 8)).x, t.texel(0, 2, 5).x);
    Texture no_mips;
    no_mips.mip = MipFilter::None;
    no_mips.min_nearest = true;
    EXPECT_EQ(lookup(no_mips, t, uv, 10).x, t.texel(0, 2, 5).x);
    no_mips.min_nearest = false;
    EXPECT_EQ(lookup(no_mips, t, uv, 10).x, lookup(Texture{}, t, uv).x);
    Texture mip_nearest;
    mip_nearest.mip = MipFilter::Nearest;
    mip_nearest.min_nearest = true;
    // Level 1 is 4 x 4: uv (0.3, 0.71) is its texel (1, 2).
    EXPECT_EQ(lookup(mip_nearest, t, uv, width_for(1.2f, 8)).x, t.texel(1, 1, 2).x);
}

// Every wrap mode at every level: a lookup outside [0, 1) equals the one its mode folds
// it to (REPEAT: shifted by whole periods; MIRRORED_REPEAT: reflected; CLAMP_TO_EDGE:
// the edge texel's centre).
TEST(Texture, WrapModesAtEveryLevel) {
    const TextureImage t = ramp();
    for (int level = 0; level < t.levels(); ++level) {
        SCOPED_TRACE(level);
        const float w = level == 0 ? 0 : width_for(float(level), 8);
        const int n = t.width(level);
        Texture repeat, mirror, clamp;
        repeat.mip = mirror.mip = clamp.mip = MipFilter::Nearest;
        mirror.wrap_s = mirror.wrap_t = WrapMode::MirroredRepeat;
        clamp.wrap_s = clamp.wrap_t = WrapMode::ClampToEdge;
        const Vec2 uv(0.37f, 0.81f);
        EXPECT_NEAR(lookup(repeat, t, {uv.x + 3, uv.y - 2}, w).x, lookup(repeat, t, uv, w).x,
                    1e-6f);
        EXPECT_NEAR(lookup(mirror, t, {-uv.x, 2 - uv.y}, w).x, lookup(mirror, t, uv, w).x, 1e-6f);
        EXPECT_NEAR(lookup(mirror, t, {uv.x + 2, uv.y}, w).x, lookup(mirror, t, uv, w).x, 1e-6f);
        const Vec2 corner(1 - 0.5f / float(n), 0.5f / float(t.height(level)));
        EXPECT_NEAR(lookup(clamp, t, {1.7f, -3.0f}, w).x, lookup(clamp, t, corner, w).x, 1e-6f);
        EXPECT_NEAR(lookup(clamp, t, corner, w).x, t.texel(level, n - 1, 0).x, 1e-6f);
        // Repeat and clamp differ at the seam, where one blends with the far side.
        if (n > 1) {
            EXPECT_NE(lookup(repeat, t, {0.0f, 0.5f}, w).x, lookup(clamp, t, {0.0f, 0.5f}, w).x);
        }
    }
}

// A distant checkerboard (checks of 4 texels, each pixel covering 8 x 8 texels): a pixel
// estimate from 4 samples jittered over its footprint converges to the board's mean
// with far less variance when the lookups are filtered over the footprint than at the
// finest level, where each sample is black or white. Level 3 (8 x 8 texels a texel) is
// flat, level 2 still shows the checks: a level of detail half a level too fine would
// fail the ratio. Both estimate the mean within the 8-bit storage of the levels (sRGB
// code 188 for 0.5: 0.3%).
TEST(Texture, MinifiedCheckerboardVarianceFiltered) {
    const int n = 256;
    TextureImage t(n, n, 1, TexelFormat::U8, true);
    uint8_t* p = static_cast<uint8_t*>(t.level0_data());
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) p[y * n + x] = (x / 4 + y / 4) % 2 ? 255 : 0;
    t.build_mips();
    const float footprint = 8.0f / n;
    Texture filtered, finest;
    finest.mip = MipFilter::None;
    Rng rng(7);
    const int pixels = 2000, spp = 4;
    double sum[2] = {0, 0}, sum2[2] = {0, 0};
    for (int i = 0; i < pixels; ++i) {
        const Vec2 centre(rng.next_float(), rng.next_float());
        double est[2] = {0, 0};
        for (int s = 0; s < spp; ++s) {
            const Vec2 uv(centre.x + (rng.next_float() - 0.5f) * footprint,
                          centre.y + (rng.next_float() - 0.5f) * footprint);
            est[0] += lookup(filtered, t, uv, footprint).x / spp;
            est[1] += lookup(finest, t, uv, footprint).x / spp;
        }
        for (int k = 0; k < 2; ++k) {
            sum[k] += est[k];
            sum2[k] += est[k] * est[k];
        }
    }
    double mean[2], var[2];
    for (int k = 0; k < 2; ++k) {
        mean[k] = sum[k] / pixels;
        var[k] = sum2[k] / pixels - mean[k] * mean[k];
    }
    // Finest: samples mostly black or white, about 0.25 / 4 a pixel.
    EXPECT_GT(var[1], 0.03);
    // Filtered: level 3 is flat (measured variance 0); half a level finer would blend in
    // level 2's checks (about 0.25 / 4 x 0.5^2 = 0.016). A ratio of 100 sits between.
    EXPECT_LT(var[0] * 100, var[1]) << var[0] << " " << var[1];
    EXPECT_NEAR(mean[0], 0.5, 0.005);
    EXPECT_NEAR(mean[1], 0.5, 4 * std::sqrt(var[1] / pixels) + 0.002);
}

// The working-space matrix applies after filtering, to RGB only.
TEST(Texture, ColourMatrixAfterTheLookup) {
    Image img(1, 1, 4);
    img.pixels = {0.2f, 0.4f, 0.6f, 0.5f};
    TextureImage t(img);
    Mat3 m = Mat3::identity();
    m.m[0][1] = 0.5;  // r' = r + g / 2
    t.set_color_matrix(m);
    const Vec4 c = lookup(Texture{}, t, {0.5f, 0.5f});
    EXPECT_FLOAT_EQ(c.x, 0.4f);
    EXPECT_FLOAT_EQ(c.y, 0.4f);
    EXPECT_FLOAT_EQ(c.w, 0.5f);
}

}  // namespace
}  // namespace penumbra
