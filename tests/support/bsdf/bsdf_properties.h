// Property checks of BSDFs beyond the hemisphere chi-square of bsdf_checks.h: sampling
// over the whole sphere (for transmission), agreement of sample() with eval()/pdf(), and
// reciprocity. Each returns an empty string on success, else what went wrong.
#pragma once

#include <string>

#include "materials/bsdf.h"
#include "support/bsdf/bsdf_checks.h"

namespace penumbra::test {

// bsdf_chi2 over the whole sphere of wi, for models that transmit (and wo below z = 0).
// 20 x 20 cells of equal solid angle.
Chi2Result bsdf_chi2_sphere(const Bsdf& bsdf, Vec3 wo, const BsdfChi2Options& options,
                            Transport mode = Transport::Radiance);

// The chi-square test for lobes too narrow to bin over the sphere (alpha 1e-3): each
// non-specular wi is binned by its microfacet normal h instead, in a disk of radius 1
// where the distance from the centre is q = t / sqrt(1 + t^2), t = tan(theta_h) / alpha,
// centred at (-1, 0) for wi on wo's side and at (1, 0) for wi on the other side (the
// half vector of refraction, Walter et al. 2007, eq. 16, with relative IOR eta; eta 0:
// reflection only, and a transmitted sample fails). The expected density is pdf()
// times the Jacobians of wi -> h -> the disk, computed here independently of the BSDF.
// Each sampled wi is binned as a uniform point of its float rounding box, since at
// grazing wo the disk is fine enough to resolve wi's float grid (alpha 1e-4).
Chi2Result bsdf_chi2_half_vector(const Bsdf& bsdf, Vec3 wo, float alpha, float eta,
                                 const BsdfChi2Options& options,
                                 Transport mode = Transport::Radiance);
// The same for an anisotropic lobe: t = |(h.x / alpha.x, h.y / alpha.y)| / h.z, and the
// disk's angle is that of the stretched slope.
Chi2Result bsdf_chi2_half_vector(const Bsdf& bsdf, Vec3 wo, Vec2 alpha, float eta,
                                 const BsdfChi2Options& options,
                                 Transport mode = Transport::Radiance);

// n samples at wo: every non-specular sample must have f and pdf equal (to relative
// rel_tol) to eval() and pdf() at its wi, a positive pdf, a unit wi and a finite weight
// equal to f |cos| / pdf; specular samples need a pdf in (0, 1] and a finite weight.
std::string check_sample_agreement(const Bsdf& bsdf, Vec3 wo, int n, uint64_t seed, Transport mode,
                                   float rel_tol = 1e-5f);

// f(wo, wi) = f(wi, wo) to relative tol for n random pairs of the upper hemisphere
// (cosines at least min_cos).
std::string check_reciprocity(const Bsdf& bsdf, int n, uint64_t seed, float tol = 1e-4f,
                              float min_cos = 0.02f);

// A random unit direction with |cos theta| in [min_cos, 1], on the upper hemisphere or
// (lower = true) the lower one.
Vec3 random_direction(Rng& rng, float min_cos = 0.02f, bool lower = false);

}  // namespace penumbra::test
