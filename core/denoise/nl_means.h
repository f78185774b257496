// Non-local means weights between pixels, from a guide image and its variance
// (Rousselle, Knaus, Zwicker 2012, "Adaptive Rendering with Non-Local Means Filtering",
// eq. 2-4), and the plain non-local means filter built on them. The per-pixel distance
// subtracts the variance the two noisy values add to their squared difference, so two
// pixels with the same mean are at distance about 0 however noisy they are; the patch
// distance averages it over the (2F + 1)^2 pixels around each and over the channels.
#pragma once

#include <vector>

#include "core/denoise/planes.h"

namespace penumbra {

struct NlmGuide {
    const Planes* guide;     // the image whose patches are compared
    const Planes* variance;  // per channel, of the guide's values
    int patch_radius;        // F
    float k;                 // bandwidth: larger weighs more distant patches more
};

// e^-x for x >= 0, to 1e-6 relative (below 10), in plain float arithmetic (vectorises, and gives
// the same bits on every x86-64 CPU, which glibc's expf with its FMA variants need not).
inline float exp_neg(float x) {
    x = x < 87.0f ? x : 87.0f;          // also catches NaN (the comparison is false)
    const float t = x * 1.44269504f;    // e^-x = 2^-t
    const int n = static_cast<int>(t);  // t >= 0: truncation is floor
    const float u = (static_cast<float>(n) - t) * 0.693147181f;  // in (-ln 2, 0]
    // e^u by its Taylor series to u^8: truncation below 1.1e-7 on (-ln 2, 0].
    float p = 1.0f / 40320;
    p = p * u + 1.0f / 5040;
    p = p * u + 1.0f / 720;
    p = p * u + 1.0f / 120;
    p = p * u + 1.0f / 24;
    p = p * u + 1.0f / 6;
    p = p * u + 0.5f;
    p = p * u + 1.0f;
    p = p * u + 1.0f;
    union {
        int i;
        float f;
    } scale{(127 - n) << 23};  // 2^-n, n <= 125
    return p * scale.f;
}

// Scratch buffers for patch_weights, reused across offsets.
struct NlmScratch {
    std::vector<float> distance, rows, numerator, denominator;
    std::vector<int> column_a, column_b;
};

// w(p, p + (dx, dy)) = exp(-max(0, patch distance)) for p = (x0 + i s, y0 + j s) in
// [x0, x1) x [y0, y1) (s: stride), row by row into out[b], for each of the nk bandwidths
// ks[b] (the guide's own k unused), which share the differences; 0 where p + (dx, dy)
// lies outside the image. Patch pixels beyond the border are clamped to it.
void patch_weights(const NlmGuide& g, const float* ks, int nk, int x0, int y0, int x1, int y1,
                   int dx, int dy, float* const* out, NlmScratch& scratch, int stride);

// Each pixel of `image` replaced by the weighted mean of the pixels within `radius`
// (a (2R + 1)^2 window), weighted by the guide's patch similarity. Deterministic.
Planes nl_means(const Planes& image, const NlmGuide& guide, int radius);

// The tile size the filters work in; tiles are independent, so the result does not
// depend on how many threads run them.
inline constexpr int kDenoiseTile = 32;

}  // namespace penumbra
