// A dielectric interface (glass, water): exact Fresnel reflection and refraction with
// total internal reflection. Smooth (Dirac lobes) below kDeltaAlpha, otherwise the rough
// model of Walter et al. 2007 with GGX or Beckmann microfacets and Smith masking.
#pragma once

#include "materials/bsdf.h"
#include "materials/lobes/microfacet.h"
#include "materials/lobes/thin_film.h"

namespace penumbra {

struct DielectricParams {
    float eta = 1.5f;  // IOR below the surface (-z) over the IOR above it (+z)
    float alpha = 0;
    MicrofacetType distribution = MicrofacetType::Ggx;
    // Smith only: the V-cavity term is defined for reflection alone.
    MaskingModel masking = MaskingModel::SmithSeparable;
    Spectrum reflectance{1, 1, 1};    // tint of the reflected part, 1 when physical
    Spectrum transmittance{1, 1, 1};  // tint of the refracted part
    // KHR_materials_iridescence: the share of a thin film's Fresnel in the interface's
    // (film_interface_reflectance, thin_film.h); 0, or a film of thickness 0, is none.
    // The film coats the +z side when film_above, else the -z side.
    float iridescence = 0;
    ThinFilm film;
    bool film_above = true;
};

// wo and wi may lie on either side. In Transport::Radiance the refracted part carries
// the (eta_wo / eta_wi)^2 factor of radiance crossing the interface (Veach 1997, sec.
// 5.2); Transport::Importance leaves it out. BsdfSample::eta is the IOR of wi's side
// over that of wo's side for refraction and 1 for reflection.
// With a film the Fresnel reflectance F is a colour: reflection takes F, refraction
// 1 - F per channel, and reflection is chosen with probability mean(F). From inside,
// the film's F is that at the outside's cosine (Snell's law), 1 beyond the critical
// angle: a film that absorbs nothing transmits alike both ways. An index-matched
// interface (eta 1) under a film reflects as a mirror whatever the roughness.
class DielectricBsdf final : public Bsdf {
public:
    static constexpr float kDeltaAlpha = 1e-4f;

    explicit DielectricBsdf(const DielectricParams& p);
    Spectrum eval(Vec3 wo, Vec3 wi, Transport mode) const override;
    float pdf(Vec3 wo, Vec3 wi, Transport mode) const override;
    std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Vec2 u, Transport mode) const override;
    bool has_specular() const override { return m_delta; }

private:
    // A pair (wo, wi) seen through its microfacet: the normal h (h.z > 0), whether wi is
    // a reflection, etap (the IOR of the far side over that of wo's side) and the
    // Fresnel reflectance of the microfacet: F without a film; with one, Fc per channel
    // and F their mean, the probability of reflection.
    struct Pair {
        Vec3 h;
        bool reflection;
        float etap;
        float woh, wih;
        float F;
        Spectrum Fc;
    };
    std::optional<Pair> pair(Vec3 wo, Vec3 wi) const;
    // The film's Fresnel reflectance per channel for a direction at cos_h (signed: > 0 on
    // the +z side) to the microfacet normal, given the bare interface's F.
    Spectrum film_fresnel(float cos_h, float F) const;
    std::optional<BsdfSample> sample_smooth(Vec3 wo, float u_lobe, Transport mode) const;
    std::optional<BsdfSample> sample_smooth_film(Vec3 wo, float u_lobe, Transport mode) const;

    DielectricParams m_p;
    MicrofacetDistribution m_dist;
    bool m_delta;
    bool m_film;
};

}  // namespace penumbra
