// measure_exposure's thresholds from both sides: a pixel is lit from 1% of display
// white, an image nearly black under 1% lit pixels, mostly clipped over half its pixels
// above display white; the exposure scales before the thresholds; non-finite is black.
#include "core/film/image_exposure.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace penumbra {
namespace {

// A 100 x 10 grey image (R = G = B = v, so luminance v): its first n pixels at `v`, the
// rest at `rest`.
Image grey(int n, float v, float rest = 0) {
    Image img(100, 10, 4);
    for (int i = 0; i < 1000; ++i) {
        const float c = i < n ? v : rest;
        img.pixels[size_t(i) * 4 + 0] = img.pixels[size_t(i) * 4 + 1] =
            img.pixels[size_t(i) * 4 + 2] = c;
        img.pixels[size_t(i) * 4 + 3] = 1;
    }
    return img;
}

TEST(ImageExposure, NearlyBlackBelowOnePercentLitPixels) {
    // 10 of 1000 pixels lit is 1%: not nearly black; 9 is.
    const ImageExposure at = measure_exposure(grey(10, 0.5f));
    EXPECT_DOUBLE_EQ(at.lit_fraction, 0.01);
    EXPECT_FALSE(at.nearly_black());
    const ImageExposure below = measure_exposure(grey(9, 0.5f));
    EXPECT_TRUE(below.nearly_black());
    EXPECT_FALSE(below.mostly_clipped());
    // An empty image is not judged.
    EXPECT_FALSE(measure_exposure(Image()).nearly_black());
}

TEST(ImageExposure, ATransparentBackgroundIsNoPartOfThePicture) {
    // 9 lit pixels among 1000 are nearly black; the same 9 with the 900 dark pixels
    // after the first 100 empty (alpha 0, a transparent background) are 9% of the picture.
    Image img = grey(9, 0.5f);
    for (int i = 100; i < 1000; ++i) img.pixels[size_t(i) * 4 + 3] = 0;
    const ImageExposure e = measure_exposure(img);
    EXPECT_EQ(e.pixels, 100u);
    EXPECT_DOUBLE_EQ(e.lit_fraction, 0.09);
    EXPECT_FALSE(e.nearly_black());
    // Nothing in view at all: nothing to judge.
    for (int i = 0; i < 100; ++i) img.pixels[size_t(i) * 4 + 3] = 0;
    EXPECT_EQ(measure_exposure(img).pixels, 0u);
    EXPECT_FALSE(measure_exposure(img).nearly_black());
}

TEST(ImageExposure, APixelIsLitFromOnePercentOfDisplayWhiteAfterExposure) {
    // Every pixel just below 1%: all dark; just at it: all lit.
    EXPECT_EQ(measure_exposure(grey(1000, 0.0099f)).lit_fraction, 0.0);
    EXPECT_EQ(measure_exposure(grey(1000, kLitLuminance)).lit_fraction, 1.0);
    // One stop up brings 0.0099 to 0.0198: lit.
    EXPECT_EQ(measure_exposure(grey(1000, 0.0099f), 1.0f).lit_fraction, 1.0);
    // Luminance, not the brightest channel: pure blue at 0.1 is 0.0072 (Rec.709).
    Image blue = grey(1000, 0);
    for (int i = 0; i < 1000; ++i) blue.pixels[size_t(i) * 4 + 2] = 0.1f;
    EXPECT_TRUE(measure_exposure(blue).nearly_black());
    EXPECT_FALSE(measure_exposure(blue, 1.0f).nearly_black());
}

TEST(ImageExposure, MostlyClippedOverHalfThePixelsAboveDisplayWhite) {
    EXPECT_FALSE(measure_exposure(grey(500, 1.01f, 0.5f)).mostly_clipped());
    const ImageExposure over = measure_exposure(grey(501, 1.01f, 0.5f));
    EXPECT_DOUBLE_EQ(over.clipped_fraction, 0.501);
    EXPECT_TRUE(over.mostly_clipped());
    EXPECT_FALSE(over.nearly_black());
    // Display white itself does not clip; the exposure decides: 0.6 x 2 = 1.2 does.
    EXPECT_EQ(measure_exposure(grey(1000, 1.0f)).clipped_fraction, 0.0);
    EXPECT_TRUE(measure_exposure(grey(1000, 0.6f), 1.0f).mostly_clipped());
}

TEST(ImageExposure, PercentilesAndNonFinitePixels) {
    // 600 pixels at 0.2, 400 at 3: the median (rank 500) is 0.2, the 99th percentile 3.
    const ImageExposure e = measure_exposure(grey(400, 3.0f, 0.2f));
    EXPECT_FLOAT_EQ(e.median, 0.2f);
    EXPECT_FLOAT_EQ(e.p99, 3.0f);
    // NaN and infinity count as black, so they neither light nor clip the image.
    const ImageExposure nan = measure_exposure(grey(1000, std::numeric_limits<float>::quiet_NaN()));
    EXPECT_TRUE(nan.nearly_black());
    EXPECT_EQ(nan.clipped_fraction, 0.0);
    const ImageExposure inf = measure_exposure(grey(1000, std::numeric_limits<float>::infinity()));
    EXPECT_TRUE(inf.nearly_black());
    EXPECT_EQ(inf.clipped_fraction, 0.0);
}

}  // namespace
}  // namespace penumbra
