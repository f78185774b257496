#include "materials/lobes/thin_film.h"

#include <algorithm>
#include <cmath>

#include "core/math/portable_math.h"

namespace penumbra {

namespace {

float sq(float x) { return x * x; }

float schlick(float f0, float c) {
    const float m = std::clamp(1 - c, 0.0f, 1.0f);
    const float m2 = m * m;
    return f0 + (1 - f0) * (m2 * m2 * m);
}

// Normal-incidence reflectance between IORs n1 and n2.
float ior_to_f0(float n2, float n1) { return sq((n2 - n1) / (n2 + n1)); }

}  // namespace

Spectrum thin_film_sensitivity(double opd, Spectrum shift) {
    // Gaussian fits of the CIE 1931 XYZ curves in wavenumber (1/m): amplitude, mean and
    // variance, the spec's values (from Belcour & Barla's supplemental code); a Gaussian's
    // Fourier transform is again one, hence the closed form.
    const double phase = 2 * M_PI * opd * 1e-9;
    const double val[3] = {5.4856e-13, 4.4201e-13, 5.2481e-13};
    const double pos[3] = {1.6810e+06, 1.7953e+06, 2.2084e+06};
    const double var[3] = {4.3278e+09, 9.3046e+09, 6.6121e+09};
    double xyz[3];
    for (int c = 0; c < 3; ++c)
        xyz[c] = val[c] * std::sqrt(2 * M_PI * var[c]) * portable_cos(pos[c] * phase + shift[c]) *
                 portable_exp(-phase * phase * var[c]);
    // X has a second, short-wavelength lobe.
    xyz[0] += 9.7470e-14 * std::sqrt(2 * M_PI * 4.5282e+09) *
              portable_cos(2.2399e+06 * phase + shift[0]) *
              portable_exp(-4.5282e+09 * phase * phase);
    for (double& v : xyz) v /= 1.0685e-7;
    // XYZ to linear Rec.709 (sRGB primaries, D65).
    return {float(3.2404542 * xyz[0] - 1.5371385 * xyz[1] - 0.4985314 * xyz[2]),
            float(-0.9692660 * xyz[0] + 1.8760108 * xyz[1] + 0.0415560 * xyz[2]),
            float(0.0556434 * xyz[0] - 0.2040259 * xyz[1] + 1.0572252 * xyz[2])};
}

Spectrum thin_film_reflectance(const ThinFilm& film, Spectrum base_f0, float cos_theta) {
    const float c1 = std::clamp(cos_theta, 0.0f, 1.0f);
    const float outside = film.outside_ior;
    // The film fades into the outside medium as its thickness goes to 0 (the spec's
    // smoothstep over 0.03 nm), so thickness 0 leaves only the base interface.
    const float t = std::clamp(film.thickness / 0.03f, 0.0f, 1.0f);
    const float ior = outside + (film.ior - outside) * (t * t * (3 - 2 * t));
    // Snell's law into the film; total internal reflection reflects everything.
    const float cos2_sq = 1 - sq(outside / ior) * (1 - c1 * c1);
    if (cos2_sq < 0) return Spectrum(1);
    const float c2 = std::sqrt(cos2_sq);

    // First interface (outside to film): reflectance and the phase of its reflection seen
    // from inside (pi - phi12; phi12 is pi when the film is optically thinner).
    const float r12 = schlick(ior_to_f0(ior, outside), c1);
    const float t121 = 1 - r12;
    const float phi21 = ior < outside ? 0.0f : float(M_PI);
    // The optical path difference of one round trip through the film.
    const double opd = 2.0 * ior * film.thickness * c2;

    Spectrum r23, phi;
    for (int c = 0; c < 3; ++c) {
        // Second interface (film to base): the base's IOR from its f0, as for a dielectric
        // in air (guarding f0 = 1).
        const float s = std::sqrt(std::clamp(base_f0[c], 0.0f, 0.9999f));
        const float base_ior = (1 + s) / (1 - s);
        r23[c] = schlick(ior_to_f0(base_ior, ior), c2);
        phi[c] = phi21 + (base_ior < ior ? float(M_PI) : 0.0f);
    }
    // Airy summation as a Fourier series in the phase (Belcour & Barla 2017, eq. 10-11):
    // the DC term C0 plus 2 Cm cos(m (2 pi opd / lambda + phi)) for m = 1, 2, each
    // integrated against the sensitivities.
    Spectrum result;
    Spectrum s1 = thin_film_sensitivity(opd, phi), s2 = thin_film_sensitivity(2 * opd, phi * 2);
    for (int c = 0; c < 3; ++c) {
        const float r123 = std::clamp(r12 * r23[c], 1e-5f, 0.9999f);
        const float sqrt_r123 = std::sqrt(r123);
        const float rs = t121 * t121 * r23[c] / (1 - r123);
        const float c0 = r12 + rs;
        const float cm1 = (rs - t121) * sqrt_r123, cm2 = cm1 * sqrt_r123;
        const float v = c0 + cm1 * 2 * s1[c] + cm2 * 2 * s2[c];
        result[c] = std::clamp(v, 0.0f, 1.0f);
    }
    return result;
}

Spectrum film_interface_reflectance(const ThinFilm& film, float factor, float eta,
                                    float cos_outside, float F) {
    const float r = (eta - 1) / (eta + 1);
    const Spectrum f_film = thin_film_reflectance(film, Spectrum(r * r), cos_outside);
    return Spectrum(F) + (f_film - Spectrum(F)) * std::clamp(factor, 0.0f, 1.0f);
}

float film_outside_cos(float cos_inside, float eta) {
    const float c = std::min(std::abs(cos_inside), 1.0f);
    const float sin2 = eta * eta * (1 - c * c);
    return sin2 < 1 ? std::sqrt(1 - sin2) : -1.0f;
}

}  // namespace penumbra
