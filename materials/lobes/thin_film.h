// Thin-film interference for KHR_materials_iridescence: the reflectance of a dielectric
// film over a base, integrated over the visible spectrum in Fourier space (Belcour &
// Barla 2017, "A Practical Extension to Microfacet Theory for the Modeling of Varying
// Iridescence"), with the spec's simplifications (Schlick interfaces, no polarization).
#pragma once

#include "core/math/vec.h"

namespace penumbra {

struct ThinFilm {
    float outside_ior = 1;  // the medium above the film (1: air)
    float ior = 1.3f;       // the film's (iridescenceIor)
    float thickness = 400;  // nm
};

// Linear Rec.709 reflectance of the film over a base with normal-incidence reflectance
// base_f0 (per channel; its IOR is inferred from f0 as for a dielectric, also for metals),
// at cos_theta between the direction and the (micro)normal in the outside medium. The
// spec's implementation notes (KHR_materials_iridescence, "Analytic Spectral
// Integration"), clamped to [0, 1]: out-of-gamut colours can leave that range.
Spectrum thin_film_reflectance(const ThinFilm& film, Spectrum base_f0, float cos_theta);

// The film on an interface that also transmits (KHR_materials_transmission): the
// reflectance mix(F, F_film, factor) per channel, F the interface's own Fresnel
// reflectance and F_film the film's over a base of relative IOR eta (the IOR beyond the
// film over that of the outside), at cos_outside, the cosine on the film's outside. The
// film absorbs nothing, so the transmitted share is 1 minus this, channel by channel.
Spectrum film_interface_reflectance(const ThinFilm& film, float factor, float eta,
                                    float cos_outside, float F);

// The cosine on the outside of an interface of relative IOR eta (as above) of a direction
// at cos_inside beyond it (Snell's law); -1 under total internal reflection.
float film_outside_cos(float cos_inside, float eta);

// The Fourier-space spectral sensitivity of the spec (XYZ Gaussian fits converted to
// Rec.709) at optical path difference opd (nm) and per-channel phase shift, exposed for
// tests: the integral over wavenumber of the sensitivity times cos(2 pi opd nu + shift),
// normalized so that opd 0, shift 0 gives about white.
Spectrum thin_film_sensitivity(double opd, Spectrum shift);

}  // namespace penumbra
