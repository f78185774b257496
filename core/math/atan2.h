// atan2 for float, inline, its octants by selects: the environment light maps every
// direction it is asked about to its image with two of them, and libm's atan2f is a call
// that branches on the octant; inline, it saves that call and its mispredicted branches
// (docs/performance.md, "Shapes of the hot path"). Also the same on every x86 machine, where
// glibc picks among its own variants by the CPU's features.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/math/vec.h"

namespace penumbra {

// atan2(y, x) in [-pi, pi], within 3 ulp of the exact value (Atan2.WithinThreeUlp; the
// worst, 2.7, where pi/4 is added to a negative atan; libm's atan2f: 1.5). Signed zeros
// as C's atan2: atan2(+-0, -0) = +-pi, atan2(+-0, +0) = +-0.
//
// The octant folds (y, x) to a = min/max(|x|, |y|) in [0, 1]. Cephes' atanf (atanf.c)
// reduces a above tan(pi/8) to (a - 1) / (a + 1) with pi/4 added; here that ratio is
// (min - max) / (min + max), so the two ranges share one division, chosen by selects.
// Its minimax polynomial on [-tan(pi/8), tan(pi/8)] gives the rest.
inline float atan2_fast(float y, float x) {
    const float ax = std::abs(x), ay = std::abs(y);
    const float mx = std::max(ax, ay), mn = std::min(ax, ay);
    const bool upper = mn > 0.4142135623730950f * mx;  // a > tan(pi/8)
    const float num = upper ? mn - mx : mn;
    const float den = upper ? mn + mx : (mx > 0 ? mx : 1.0f);  // (0, 0): atan 0
    const float t = num / den;
    const float z = t * t;
    float r = (((8.05374449538e-2f * z - 1.38776856032e-1f) * z + 1.99777106478e-1f) * z -
               3.33329491539e-1f) *
                  z * t +
              t;
    if (upper) r += kPi / 4;
    if (ay > ax) r = kPi / 2 - r;
    if (std::signbit(x)) r = kPi - r;
    return std::signbit(y) ? -r : r;
}

}  // namespace penumbra
