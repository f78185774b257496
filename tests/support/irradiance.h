// Analytic irradiance for tests of light transport against known answers.
#pragma once

#include <cmath>

#include "core/math/vec.h"

namespace penumbra::test {

// Irradiance at the point under the centre of a Lambertian square of side s and radiance
// L, parallel at height h: four corner rectangles of the configuration factor
// F = (1 / 2 pi) [X / sqrt(1 + X^2) atan(Y / sqrt(1 + X^2)) + (X <-> Y)] (Howell's
// catalogue, B-3), X = Y = s / 2h, and E = pi L F.
inline double square_irradiance(double L, double s, double h) {
    const double x = s / (2 * h), r = std::sqrt(1 + x * x);
    const double F = 2 * (x / r) * std::atan(x / r) / (2 * kPi);
    return kPi * L * 4 * F;
}

}  // namespace penumbra::test
