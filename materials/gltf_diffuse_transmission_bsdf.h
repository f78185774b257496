// The glTF material with KHR_materials_diffuse_transmission (and optionally
// _transmission): metallic M + (1 - M)((1 - t) fresnel_mix(mix(diffuse_brdf,
// diffuse_btdf, dt), specular) + t specular_btdf), written as a mixture of four models.
#pragma once

#include <variant>

#include "materials/lobes/dielectric.h"
#include "materials/lobes/diffuse_transmission.h"
#include "materials/metal_rough_bsdf.h"
#include "materials/lobes/thin_dielectric.h"

namespace penumbra {

struct DiffuseTransmissionParams {
    float factor = 0;         // diffuseTransmission (factor x texture A), [0, 1]
    Spectrum color{1, 1, 1};  // diffuseTransmissionColor (factor x texture RGB)
};

// eval(M) of MetalRoughBsdf is linear in the metallic M, so the material is
//     M MetalRough(M = 1) + (1 - M)(1 - t) [MetalRough(M = 0, base (1 - dt))
//                                          + DiffuseTransmissionLobe(dt color)]
//   + (1 - M) t Dielectric,
// each term chosen with a probability from its weight and rough albedo at wo; eval is
// the weighted sum and pdf the mixture, so sample, eval and pdf agree. The diffuse
// reflection and transmission share the specular layer's transmittance, so a white
// material with white transmission colour loses nothing to the split.
class GltfDiffuseTransmissionBsdf final : public Bsdf {
public:
    GltfDiffuseTransmissionBsdf(const MetalRoughParams& p, const DiffuseTransmissionParams& dt,
                                float transmission, const DielectricParams& dielectric,
                                bool thin_walled = false);
    Spectrum eval(Vec3 wo, Vec3 wi, Transport mode) const override;
    // The opaque part's diffuse reflection and the diffuse transmission lobe.
    Spectrum eval_diffuse(Vec3 wo, Vec3 wi, Transport mode) const override;
    float pdf(Vec3 wo, Vec3 wi, Transport mode) const override;
    std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Vec2 u, Transport mode) const override;
    bool has_specular() const override;

private:
    enum Component { kMetal, kOpaque, kDiffuseTransmission, kGlass, kCount };
    static MetalRoughParams with_metallic(MetalRoughParams p, float metallic, float base_scale);
    // Probabilities of choosing each component for this wo (sum 1).
    void probabilities(Vec3 wo, float q[kCount]) const;
    Spectrum eval_component(int c, Vec3 wo, Vec3 wi, Transport mode) const;
    float pdf_component(int c, Vec3 wo, Vec3 wi, Transport mode) const;

    float m_w[kCount];       // mixture weights
    Spectrum m_opaque_base;  // base colour x (1 - dt), for the sampling weights
    float m_f0_max, m_f90;
    MetalRoughBsdf m_metal;
    MetalRoughBsdf m_opaque;
    DiffuseTransmissionLobe m_dt;
    // thin_walled (no KHR_materials_volume): a sheet that does not bend what it
    // transmits, as in GltfTransmissionBsdf.
    const Bsdf& glass() const {
        return std::visit([](const auto& b) -> const Bsdf& { return b; }, m_glass);
    }
    std::variant<DielectricBsdf, ThinDielectricBsdf> m_glass;
};

}  // namespace penumbra
