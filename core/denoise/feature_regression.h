// Collaborative first-order regression (NFOR, section 4): around every pixel j, a
// weighted least-squares fit of the colour as an affine function of the guide features
// over a (2R + 1)^2 window, with non-local means weights from the colour; each fit then
// predicts every pixel of its window, and a pixel's result is the weighted mean of the
// predictions of all fits that cover it. A linear model in the features follows texture
// and shading edges that a plain average would blur.
#pragma once

#include <vector>

#include "core/denoise/planes.h"

namespace penumbra {

struct RegressionParams {
    int window_radius = 9;  // R
    int patch_radius = 3;   // F of the colour weights
    // Fits are centred on every S-th pixel of every S-th row: each pixel still gets the
    // predictions of about (2R + 1)^2 / S^2 overlapping fits, at 1 / S^2 of the cost.
    int center_stride = 2;
};

// color, variance: 3 channels (variance of color's values); features: up to 15 channels.
// One result per bandwidth k of the colour weights (up to 4; they share all work but the
// weights and the sums). Deterministic: tiles are fitted apart and their predictions
// summed in a fixed order.
std::vector<Planes> collaborative_regression(const Planes& color, const Planes& variance,
                                             const Planes& features, const RegressionParams& params,
                                             const std::vector<float>& ks);

}  // namespace penumbra
