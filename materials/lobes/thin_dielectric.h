// A thin-walled dielectric sheet (glTF KHR_materials_transmission without
// KHR_materials_volume): light reflects or passes through without being bent, since
// both sides of the sheet are the same medium. Smooth below kDeltaAlpha, else rough.
#pragma once

#include "materials/bsdf.h"
#include "materials/lobes/dielectric.h"
#include "materials/lobes/microfacet.h"

namespace penumbra {

// Smooth: pbrt-v4's ThinDielectricBxDF (sec. 9.5.1): reflectance R' = R + T^2 R / (1 -
// R^2) sums the sheet's inter-reflections, transmission 1 - R' goes straight on (wi =
// -wo). Rough: the microfacet reflection lobe of Walter et al. 2007 with Fresnel R'(wo.h),
// and its transmitted part 1 - R' is that lobe mirrored through the surface plane (the
// glTF Sample Viewer's thin-walled BTDF, KHR_materials_transmission's "thin" model).
// Reflection and transmission together are the rough mirror's lobe without Fresnel, so
// the sheet never gains energy and loses only what single-scattering GGX loses.
// DielectricParams::eta is the sheet's IOR over that of the medium on both sides; the
// model is reciprocal, needs no eta^2 factor, and BsdfSample::eta is always 1.
// A film (DielectricParams::iridescence) coats one face: that face reflects R1 =
// mix(R, F_film, factor) per channel (film_interface_reflectance), the other R, and the
// incoherent sum over the sheet, R' = (R1 + R - 2 R1 R) / (1 - R1 R), is the same from
// either side. R' is a colour, transmission takes 1 - R' per channel, and reflection is
// chosen with probability mean(R').
class ThinDielectricBsdf final : public Bsdf {
public:
    static constexpr float kDeltaAlpha = DielectricBsdf::kDeltaAlpha;

    explicit ThinDielectricBsdf(const DielectricParams& p);
    Spectrum eval(Vec3 wo, Vec3 wi, Transport mode) const override;
    float pdf(Vec3 wo, Vec3 wi, Transport mode) const override;
    std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Vec2 u, Transport mode) const override;
    bool has_specular() const override { return m_delta; }

    // R' of a sheet of relative IOR eta at incidence cosine cos_theta (either sign).
    static float sheet_reflectance(float cos_theta, float eta);
    // R' per channel with the film (the one above without).
    Spectrum reflectance(float cos_theta) const;

private:
    // A pair (wo, wi) seen through its microfacet: wi (mirrored back to wo's side when
    // transmitted) is the reflection of wo about h (h.z > 0).
    struct Pair {
        Vec3 h;
        Vec3 wr;  // wi on wo's side
        bool reflection;
        float woh;
    };
    std::optional<Pair> pair(Vec3 wo, Vec3 wi) const;

    DielectricParams m_p;
    MicrofacetDistribution m_dist;
    bool m_delta;
    bool m_film;
};

}  // namespace penumbra
