// sin, cos and exp computed by our own code, for results on the way to a pixel. glibc
// picks FMA or SSE2 variants of its maths functions at run time, and they round
// differently for a few arguments (sinf, cosf and sincosf 1 to 6 in 1e8 floats; the
// double sin, cos and exp far more often), so the same render could differ between CPUs.
// These are plain double arithmetic, compiled without FMA (ISO C++, baseline x86-64):
// the same bits on every x86-64 CPU. Cody-Waite reduction and fdlibm's kernel
// polynomials (Sun Microsystems, 1993), accurate to about 1 ulp in double for |x| up to
// 1e5 (tested); the float versions round that once. Larger arguments are reduced less
// accurately, still deterministically.
#pragma once

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>

namespace penumbra {

namespace portable_detail {

// x = n pi/2 + r, |r| <= pi/4 (a little more where x * 2/pi rounds); q = n mod 4. For
// |x| <= 2^30 (the caller's range): n by the 1.5 x 2^52 trick, which rounds to an
// integer in two exact additions (std::floor is a call on baseline x86-64).
inline double reduce_half_pi(double x, int* q) {
    constexpr double kTwoOverPi = 6.36619772367581382433e-01;
    constexpr double kPio2_1 = 1.57079632673412561417e+00;   // first 33 bits of pi/2
    constexpr double kPio2_2 = 6.07710050630396597660e-11;   // next 33 bits
    constexpr double kPio2_2t = 2.02226624879595063154e-21;  // pi/2 - kPio2_1 - kPio2_2
    constexpr double kRound = 0x1.8p52;
    const double n = (x * kTwoOverPi + kRound) - kRound;
    *q = static_cast<int>(static_cast<int64_t>(n) & 3);
    return ((x - n * kPio2_1) - n * kPio2_2) - n * kPio2_2t;
}

// fdlibm's __kernel_sin and __kernel_cos polynomials on |r| <= pi/4.
inline double kernel_sin(double r) {
    const double z = r * r;
    return r + r * z *
                   (-1.66666666666666324348e-01 +
                    z * (8.33333333332248946124e-03 +
                         z * (-1.98412698298579493134e-04 +
                              z * (2.75573137070700676789e-06 +
                                   z * (-2.50507602534068634195e-08 +
                                        z * 1.58969099521155010221e-10)))));
}
inline double kernel_cos(double r) {
    const double z = r * r;
    return 1.0 - 0.5 * z +
           z * z *
               (4.16666666666666019037e-02 +
                z * (-1.38888888888741095749e-03 +
                     z * (2.48015872894767294178e-05 +
                          z * (-2.75573143513906633035e-07 +
                               z * (2.08757232129817482790e-09 +
                                    z * -1.13596475577881948265e-11)))));
}

}  // namespace portable_detail

// sin x and cos x in double.
inline void portable_sincos(double x, double* s, double* c) {
    if (!std::isfinite(x)) {
        *s = *c = std::numeric_limits<double>::quiet_NaN();
        return;
    }
    if (x == 0) {  // keeps sin(-0) = -0
        *s = x;
        *c = 1;
        return;
    }
    // Beyond 2^30 the three-part reduction loses every bit; fmod by 2 pi (as a double)
    // is exact and keeps the result in [-1, 1], though no closer to the true sine.
    if (std::abs(x) > 0x1p30) x = std::fmod(x, 6.28318530717958623200);
    int q;
    const double r = portable_detail::reduce_half_pi(x, &q);
    const double sr = portable_detail::kernel_sin(r), cr = portable_detail::kernel_cos(r);
    switch (q) {
        case 0:
            *s = sr;
            *c = cr;
            break;
        case 1:
            *s = cr;
            *c = -sr;
            break;
        case 2:
            *s = -sr;
            *c = -cr;
            break;
        default:
            *s = -cr;
            *c = sr;
            break;
    }
}
inline double portable_sin(double x) {
    double s, c;
    portable_sincos(x, &s, &c);
    return s;
}
inline double portable_cos(double x) {
    double s, c;
    portable_sincos(x, &s, &c);
    return c;
}

// The float versions: the double result rounded once.
inline void portable_sincos(float x, float* s, float* c) {
    double sd, cd;
    portable_sincos(double(x), &sd, &cd);
    *s = static_cast<float>(sd);
    *c = static_cast<float>(cd);
}
inline float portable_sin(float x) { return static_cast<float>(portable_sin(double(x))); }
inline float portable_cos(float x) { return static_cast<float>(portable_cos(double(x))); }

// e^x in double: x = k ln 2 + r, |r| <= ln 2 / 2, e^r by its Taylor series to r^13
// (truncation under 2e-15 relative), times 2^k exactly.
inline double portable_exp(double x) {
    if (std::isnan(x)) return x;
    if (x > 709.78) return std::numeric_limits<double>::infinity();
    if (x < -745.2) return 0.0;
    constexpr double kLn2Hi = 6.93147180369123816490e-01;  // 32 bits: k kLn2Hi is exact
    constexpr double kLn2Lo = 1.90821492927058770002e-10;
    constexpr double kInvLn2 = 1.44269504088896338700e+00;
    const double k = std::floor(x * kInvLn2 + 0.5);
    const double r = (x - k * kLn2Hi) - k * kLn2Lo;
    double p = 1.0 / 6227020800.0;  // 1/13!
    for (double d : {479001600.0, 39916800.0, 3628800.0, 362880.0, 40320.0, 5040.0, 720.0, 120.0,
                     24.0, 6.0, 2.0, 1.0, 1.0})
        p = p * r + 1.0 / d;
    return std::ldexp(p, static_cast<int>(k));
}

}  // namespace penumbra
