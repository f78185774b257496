// KHR_materials_dispersion: the IOR at the wavelength an RGB channel stands for, from the
// material's IOR (at the d line) and its dispersion (20 / Abbe number).
#pragma once

#include <algorithm>

namespace penumbra {

// The wavelength (nm) each RGB channel refracts at: the Fraunhofer C, d and F lines that
// define the Abbe number V_d = (n_d - 1) / (n_F - n_C). Green keeps the material's IOR,
// as the extension's implementation note gives green n_d, and red to blue spans exactly
// the Abbe spread n_F - n_C (the note uses half of it on each side of green; Cauchy's
// law puts C 0.30 and F 0.70 of it from d).
constexpr float kDispersionWavelength[3] = {656.27f, 587.56f, 486.13f};

// The extension's Cauchy fit: n(lambda) = max(n_d + (n_d - 1) / V_d (523655 / lambda^2 -
// 1.5168), 1), with 1 / V_d = dispersion / 20 (KHR_materials_dispersion README). channel
// -1, or dispersion 0, is the IOR itself, bit for bit.
inline float dispersion_ior(float ior, float dispersion, int channel) {
    if (channel < 0 || !(dispersion > 0)) return ior;
    const float lambda = kDispersionWavelength[channel];
    return std::max(ior + (ior - 1) * (dispersion / 20) * (523655 / (lambda * lambda) - 1.5168f),
                    1.0f);
}

}  // namespace penumbra
