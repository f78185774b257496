// How far an image is from a reference: MSE and relative MSE over R, G and B.
#pragma once

#include "core/image.h"

namespace penumbra {

// The relMSE epsilon: keeps black reference pixels from dominating. 1e-2, as in
// Rousselle et al. 2011 and most denoising papers that report relMSE.
inline constexpr double kRelMseEpsilon = 1e-2;

// Mean over pixels and the R, G, B channels of (x - r)^2. Sizes must match (CHECK).
double mean_squared_error(const Image& image, const Image& reference);
// Mean of (x - r)^2 / (r^2 + epsilon) over pixels and R, G, B.
double relative_mse(const Image& image, const Image& reference,
                    double epsilon = kRelMseEpsilon);

}  // namespace penumbra
