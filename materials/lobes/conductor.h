// Metals: conductor Fresnel with a complex IOR (eta + i k per RGB channel) on a perfect
// mirror (alpha below CookTorranceBsdf::kDeltaAlpha) or on a rough Cook-Torrance lobe
// with GGX or Beckmann microfacets.
#pragma once

#include "materials/lobes/cook_torrance.h"

namespace penumbra {

class ConductorBsdf final : public Bsdf {
public:
    ConductorBsdf(const ComplexIor& ior, MicrofacetType distribution, float alpha,
                  MaskingModel masking = MaskingModel::SmithCorrelated);
    ConductorBsdf(Metal metal, MicrofacetType distribution, float alpha)
        : ConductorBsdf(metal_ior(metal), distribution, alpha) {}

    Spectrum eval(Vec3 wo, Vec3 wi, Transport mode) const override {
        return m_lobe.eval(wo, wi, mode);
    }
    float pdf(Vec3 wo, Vec3 wi, Transport mode) const override { return m_lobe.pdf(wo, wi, mode); }
    std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Vec2 u, Transport mode) const override {
        return m_lobe.sample(wo, u_lobe, u, mode);
    }
    bool has_specular() const override { return m_lobe.has_specular(); }

private:
    static CookTorranceParams params(const ComplexIor& ior, MicrofacetType distribution,
                                     float alpha, MaskingModel masking);
    CookTorranceBsdf m_lobe;
};

}  // namespace penumbra
