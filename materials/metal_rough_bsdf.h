// The glTF 2.0 metallic-roughness BRDF (spec Appendix B, with KHR_materials_specular
// and _ior): a GGX (or, for comparisons, Beckmann) specular lobe with height-correlated
// Smith masking and Schlick Fresnel, over a Lambertian base weighted by 1 - F.
// Roughness 0 makes the specular lobe a perfect mirror.
#pragma once

#include "materials/bsdf.h"
#include "materials/microfacet.h"

namespace penumbra {

struct MetalRoughParams {
    Spectrum base_color{1, 1, 1};
    float metallic = 1;
    float alpha = 1;                  // roughness^2
    Spectrum dielectric_f0{0.04f};    // ((ior-1)/(ior+1))^2 * specularColor * specular
    float dielectric_f90 = 1;         // specular factor
    // GGX as the spec says; Beckmann to compare (the --microfacet switch).
    MicrofacetType distribution = MicrofacetType::Ggx;
};

class MetalRoughBsdf final : public Bsdf {
public:
    // Below this alpha the specular lobe is treated as a Dirac delta.
    static constexpr float kDeltaAlpha = 1e-4f;

    explicit MetalRoughBsdf(const MetalRoughParams& p);
    Spectrum eval(Vec3 wo, Vec3 wi, Transport mode) const override;
    float pdf(Vec3 wo, Vec3 wi, Transport mode) const override;
    std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Vec2 u,
                                     Transport mode) const override;
    bool has_specular() const override { return m_delta; }

private:
    // Mixed Fresnel of the dielectric and metal layers at cos(theta) = c.
    Spectrum specular_fresnel(float c) const;
    Spectrum diffuse_term(float cos_vh) const;
    // Probability of choosing the specular lobe for this wo.
    float specular_probability(Vec3 wo) const;
    float pdf_specular(Vec3 wo, Vec3 wi) const;

    MetalRoughParams m_p;
    MicrofacetDistribution m_dist;
    bool m_delta;
};

}  // namespace penumbra
