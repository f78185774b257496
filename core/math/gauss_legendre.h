// Gauss-Legendre quadrature on [0, 1], for the albedo tables that materials build once
// (specular_albedo, sheen_albedo).
#pragma once

#include <cmath>
#include <vector>

#include "core/math/portable_math.h"

namespace penumbra {

// Nodes x and weights w of the n-point rule on [0, 1] (weights sum to 1), by Newton's
// method on the Legendre polynomial from the usual Chebyshev-like initial guesses.
inline void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w) {
    x.resize(n);
    w.resize(n);
    const double pi = std::acos(-1.0);
    for (int i = 0; i < n; ++i) {
        double z = portable_cos(pi * (i + 0.75) / (n + 0.5)), dp = 1;
        for (int it = 0; it < 100; ++it) {
            double p1 = 1, p0 = 0;
            for (int j = 1; j <= n; ++j) {
                const double pm = p0;
                p0 = p1;
                p1 = ((2 * j - 1) * z * p0 - (j - 1) * pm) / j;
            }
            dp = n * (z * p1 - p0) / (z * z - 1);
            const double step = p1 / dp;
            z -= step;
            if (std::abs(step) < 1e-15) break;
        }
        x[i] = 0.5 * (1 - z);
        w[i] = 1 / ((1 - z * z) * dp * dp);
    }
}

}  // namespace penumbra
