// Microfacet reflection f = F D G / (4 |n.wo| |n.wi|) (Cook & Torrance 1982; Walter et al.
// 2007, eq. 20), D, G and F chosen per material (GGX/Beckmann; Smith correlated/separable,
// V-cavity; Schlick/dielectric/conductor). Below kDeltaAlpha: a mirror scaled by F.
#pragma once

#include "materials/bsdf.h"
#include "materials/lobes/fresnel.h"
#include "materials/lobes/microfacet.h"

namespace penumbra {

struct CookTorranceParams {
    MicrofacetType distribution = MicrofacetType::Ggx;
    float alpha = 0.1f;
    MaskingModel masking = MaskingModel::SmithCorrelated;
    Fresnel fresnel;          // Schlick with f0 = 1 (a white reflector) by default
    Spectrum scale{1, 1, 1};  // extra tint, 1 for physical materials
};

class CookTorranceBsdf final : public Bsdf {
public:
    // Below this alpha the lobe is a Dirac delta (as MetalRoughBsdf::kDeltaAlpha).
    static constexpr float kDeltaAlpha = 1e-4f;

    explicit CookTorranceBsdf(const CookTorranceParams& p);
    Spectrum eval(Vec3 wo, Vec3 wi, Transport mode) const override;
    float pdf(Vec3 wo, Vec3 wi, Transport mode) const override;
    std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Vec2 u, Transport mode) const override;
    bool has_specular() const override { return m_delta; }

private:
    // The half vector of a reflection pair on the upper side; empty when there is none.
    static std::optional<Vec3> half_vector(Vec3 wo, Vec3 wi);

    CookTorranceParams m_p;
    MicrofacetDistribution m_dist;
    bool m_delta;
};

}  // namespace penumbra
