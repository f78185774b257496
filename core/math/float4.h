// Four floats side by side, one operation for all four: SSE where the target has it (every
// x86-64), else a plain array the compiler may vectorise. Each operation is the scalar one
// lane by lane (IEEE arithmetic, no fused multiply-add), so code written with F4 gives the
// bits that the same formula on floats gives. For the light BVH's four children at once,
// and for Vec3 arithmetic on the hot path (a Vec3 in lanes 0-2): GCC compiles Vec3's
// operators to three scalar instructions each and does not pack them.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "core/math/vec.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace penumbra {

#if defined(__SSE2__)
struct F4 {
    __m128 v;
    F4() = default;
    explicit F4(__m128 x) : v(x) {}
    F4(float x) : v(_mm_set1_ps(x)) {}  // NOLINT: broadcasts, as the scalar formulas read
    // Four floats at p, 16-byte aligned.
    static F4 load(const float* p) { return F4(_mm_load_ps(p)); }
    // Four floats at p, any alignment (a Vec3 followed by another float: lanes 0-2).
    static F4 loadu(const float* p) { return F4(_mm_loadu_ps(p)); }
    void store(float* p) const { _mm_store_ps(p, v); }
    // A Vec3 in lanes 0-2 (lane 3 is 0), read as 8 + 4 bytes: never past its end.
    static F4 load3(const Vec3& a) {
        const __m128 xy = _mm_castpd_ps(_mm_load_sd(reinterpret_cast<const double*>(&a.x)));
        return F4(_mm_movelh_ps(xy, _mm_load_ss(&a.z)));
    }
    Vec3 xyz() const {
        return {_mm_cvtss_f32(v), _mm_cvtss_f32(_mm_shuffle_ps(v, v, 1)),
                _mm_cvtss_f32(_mm_movehl_ps(v, v))};
    }
    float lane0() const { return _mm_cvtss_f32(v); }
    float lane1() const { return _mm_cvtss_f32(_mm_shuffle_ps(v, v, 1)); }
    // Lane i in all four.
    template <int i>
    F4 broadcast() const {
        return F4(_mm_shuffle_ps(v, v, _MM_SHUFFLE(i, i, i, i)));
    }
};
inline F4 operator+(F4 a, F4 b) { return F4(_mm_add_ps(a.v, b.v)); }
inline F4 operator-(F4 a, F4 b) { return F4(_mm_sub_ps(a.v, b.v)); }
inline F4 operator*(F4 a, F4 b) { return F4(_mm_mul_ps(a.v, b.v)); }
inline F4 operator/(F4 a, F4 b) { return F4(_mm_div_ps(a.v, b.v)); }
inline F4 sqrt4(F4 a) { return F4(_mm_sqrt_ps(a.v)); }
// As SSE's min/max: the second operand when either is NaN.
inline F4 min4(F4 a, F4 b) { return F4(_mm_min_ps(a.v, b.v)); }
inline F4 max4(F4 a, F4 b) { return F4(_mm_max_ps(a.v, b.v)); }
// Masks are all-ones lanes, as SSE's comparisons give them.
inline F4 gt(F4 a, F4 b) { return F4(_mm_cmpgt_ps(a.v, b.v)); }
// m ? a : b, lane by lane.
inline F4 select(F4 m, F4 a, F4 b) {
    return F4(_mm_or_ps(_mm_and_ps(m.v, a.v), _mm_andnot_ps(m.v, b.v)));
}
// a with the bits of mask cleared (mask: sign bits, so |a| where set; 16-byte aligned).
inline F4 clear_bits(F4 a, const uint32_t* mask) {
    return F4(_mm_andnot_ps(_mm_load_ps(reinterpret_cast<const float*>(mask)), a.v));
}
inline F4 abs4(F4 a) { return F4(_mm_andnot_ps(_mm_set1_ps(-0.0f), a.v)); }
// Lane 0: (a0 + a1) + a2, lane 1: (b0 + b1) + b2, the sums dot() forms, so two dot
// products come from their lane-wise products in five instructions; lanes 2-3 unspecified.
inline F4 sum3_pair(F4 a, F4 b) {
    const __m128 lo = _mm_unpacklo_ps(a.v, b.v);  // a0 b0 a1 b1
    const __m128 hi = _mm_unpackhi_ps(a.v, b.v);  // a2 b2 a3 b3
    return F4(_mm_add_ps(_mm_add_ps(lo, _mm_movehl_ps(lo, lo)), hi));
}
#else
struct F4 {
    float v[4];
    F4() = default;
    F4(float x) : v{x, x, x, x} {}  // NOLINT: broadcasts, as the scalar formulas read
    F4(float a, float b, float c, float d) : v{a, b, c, d} {}
    static F4 load(const float* p) { return {p[0], p[1], p[2], p[3]}; }
    static F4 loadu(const float* p) { return {p[0], p[1], p[2], p[3]}; }
    void store(float* p) const { std::copy(v, v + 4, p); }
    static F4 load3(const Vec3& a) { return {a.x, a.y, a.z, 0.0f}; }
    Vec3 xyz() const { return {v[0], v[1], v[2]}; }
    float lane0() const { return v[0]; }
    float lane1() const { return v[1]; }
    template <int i>
    F4 broadcast() const {
        return F4(v[i]);
    }
};
template <typename Op>
F4 lanes(F4 a, F4 b, Op op) {
    return {op(a.v[0], b.v[0]), op(a.v[1], b.v[1]), op(a.v[2], b.v[2]), op(a.v[3], b.v[3])};
}
inline F4 operator+(F4 a, F4 b) {
    return lanes(a, b, [](float x, float y) { return x + y; });
}
inline F4 operator-(F4 a, F4 b) {
    return lanes(a, b, [](float x, float y) { return x - y; });
}
inline F4 operator*(F4 a, F4 b) {
    return lanes(a, b, [](float x, float y) { return x * y; });
}
inline F4 operator/(F4 a, F4 b) {
    return lanes(a, b, [](float x, float y) { return x / y; });
}
inline F4 sqrt4(F4 a) {
    return lanes(a, a, [](float x, float) { return std::sqrt(x); });
}
inline F4 min4(F4 a, F4 b) {
    return lanes(a, b, [](float x, float y) { return x < y ? x : y; });
}
inline F4 max4(F4 a, F4 b) {
    return lanes(a, b, [](float x, float y) { return x > y ? x : y; });
}
inline F4 gt(F4 a, F4 b) {
    return lanes(a, b, [](float x, float y) {
        const uint32_t m = x > y ? ~0u : 0u;
        float f;
        std::memcpy(&f, &m, sizeof f);
        return f;
    });
}
inline F4 select(F4 m, F4 a, F4 b) {
    F4 r;
    for (int k = 0; k < 4; ++k) {
        uint32_t bits;
        std::memcpy(&bits, &m.v[k], sizeof bits);
        r.v[k] = bits ? a.v[k] : b.v[k];
    }
    return r;
}
inline F4 clear_bits(F4 a, const uint32_t* mask) {
    F4 r;
    for (int k = 0; k < 4; ++k) r.v[k] = mask[k] ? std::abs(a.v[k]) : a.v[k];
    return r;
}
inline F4 abs4(F4 a) {
    return lanes(a, a, [](float x, float) { return std::abs(x); });
}
inline F4 sum3_pair(F4 a, F4 b) {
    return {(a.v[0] + a.v[1]) + a.v[2], (b.v[0] + b.v[1]) + b.v[2], 0.0f, 0.0f};
}
#endif

}  // namespace penumbra
