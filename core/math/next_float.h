// The neighbouring floats of a value, by stepping its bit pattern (pbrt-v4's NextFloatUp
// and NextFloatDown): std::nextafter's results towards +-infinity, without a libm call.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace penumbra {

// Consecutive floats of one sign have consecutive bit patterns (IEEE 754 orders them by
// magnitude), so a step away from zero adds one, a step towards zero subtracts one; both
// zeros step to the smallest subnormal of the direction's sign.
inline float next_float_up(float v) {
    if (!(v < std::numeric_limits<float>::infinity())) return v;  // +inf and NaN stay
    if (v == 0) v = 0.0f;                                           // -0 steps as +0
    uint32_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    bits = v >= 0 ? bits + 1 : bits - 1;
    std::memcpy(&v, &bits, sizeof bits);
    return v;
}

inline float next_float_down(float v) {
    if (!(v > -std::numeric_limits<float>::infinity())) return v;  // -inf and NaN stay
    if (v == 0) v = -0.0f;                                           // +0 steps as -0
    uint32_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    bits = v <= 0 ? bits + 1 : bits - 1;
    std::memcpy(&v, &bits, sizeof bits);
    return v;
}

}  // namespace penumbra
