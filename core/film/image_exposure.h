// How a display would show a linear image: the fraction of its pixels that are lit and
// the fraction that clip, after the exposure. The measure behind the default-light
// rule's look at the view and the warning after a nearly black or blown-out render
// (docs/conventions.md, "Dark and blown-out images").
#pragma once

#include <cstddef>

#include "core/image.h"

namespace penumbra {

// A pixel is lit when its exposed luminance reaches 1% of display white (1.0): sRGB
// encodes 0.01 as 25/255, the darkest grey a display shows clearly apart from black.
constexpr float kLitLuminance = 0.01f;
// An image is nearly black when fewer than 1% of its pixels are lit.
constexpr double kMinLitFraction = 0.01;
// A pixel clips when its exposed luminance exceeds display white; an image is mostly
// clipped when more than half of its pixels do.
constexpr float kClipLuminance = 1.0f;
constexpr double kMaxClippedFraction = 0.5;
// Where an exposure suggestion puts a mostly clipped image's median: 18% grey.
constexpr float kMiddleGrey = 0.18f;

struct ImageExposure {
    size_t pixels = 0;  // measured
    double lit_fraction = 0;      // exposed luminance >= kLitLuminance
    double clipped_fraction = 0;  // exposed luminance > kClipLuminance
    // Exposed luminance at the median and the 99th percentile (nearest rank).
    float median = 0, p99 = 0;

    bool nearly_black() const { return pixels > 0 && lit_fraction < kMinLitFraction; }
    bool mostly_clipped() const { return clipped_fraction > kMaxClippedFraction; }
};

// Measures the RGB channels of image (linear, Rec.709 luminance weights) scaled by
// 2^exposure. Non-finite pixels count as black; pixels of alpha 0 (a transparent
// background's, where no camera ray found geometry) are left out, `pixels` counting the rest.
ImageExposure measure_exposure(const Image& image, float exposure = 0);

}  // namespace penumbra
