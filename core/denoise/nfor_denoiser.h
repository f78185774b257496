// A feature-guided denoiser after NFOR (Bitterli et al. 2016, "Nonlinearly Weighted
// First-order Regression for Denoising Monte Carlo Renderings"): per pixel, a weighted
// least-squares fit of the colour as a linear function of the guide features over a
// window, with non-local-means weights from the colour; each half of the samples is
// filtered apart at two bandwidths, the other half cross-validates the choice per
// pixel, and the same comparison gives the error estimate.
#pragma once

#include <string>

#include "core/denoise/denoise_input.h"
#include "core/image.h"

namespace penumbra {

struct NforParams {
    int window_radius = 9;  // regression window: (2r + 1)^2 pixels
    // A second, small window fitted beside it, and the per-pixel choice takes either: a
    // first-order fit over 19 x 19 pixels follows neither light falloff across a floor
    // nor shading across a small sphere, which at 160 pixels wide are nonlinear within the
    // window (32 spp, relMSE against 8192 spp: soft-shadows 2.1e-4 with 19 x 19 alone,
    // 6.8e-5 with 7 x 7 alone, 7.0e-5 with both; dof 2.7e-4, 2.8e-4, 2.4e-4; glossy
    // 8.0e-3, 7.8e-3, 6.6e-3).
    int small_window_radius = 3;
    // Non-local means patch for the regression's weights. NFOR's 7 x 7 cost 10% more time
    // and left a higher error on the bundled scenes (cornell-box at 64 spp: 4.3e-3 against
    // 3.4e-3; the others within 10%).
    int patch_radius = 2;
    float k_small = 0.5f;  // the two bandwidths the halves choose between
    float k_large = 1.0f;
    // Guide prefiltering: window and patch. NFOR's 11 x 11 and 7 x 7 took a third of the
    // time and were no better on the bundled scenes (relMSE within 3%, mostly lower).
    int feature_window_radius = 3;
    int feature_patch_radius = 1;
    int center_stride = 2;  // fits centred on every 2nd pixel of every 2nd row
};

struct DenoiseResult {
    Image color;  // 3 channels, working space
    // Estimated relMSE of `color` (kRelMseEpsilon), from the halves' cross-validation, and
    // that estimate's standard error; where the estimate is below its standard error, the
    // standard error (nfor_denoiser.cpp).
    double relmse_estimate = 0;
    double relmse_estimate_stderr = 0;
    // Pixel values (per half) that the firefly guard held back.
    size_t fireflies = 0;
    // The share of the image's energy (the sum of R, G, B over all pixels) they held:
    // the bias the guard adds to the image's mean.
    double firefly_energy = 0;
};

// Deterministic: the same bits for any thread count.
DenoiseResult denoise_nfor(const DenoiseInput& input, const NforParams& params = {});

// "NFOR (window 19x19, patch 7x7, k 0.5/1, ...)": the method and its parameters, for the
// EXR header and the summary.
std::string describe(const NforParams& params);

}  // namespace penumbra
