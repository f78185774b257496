// glTF with KHR_materials_transmission: the extension's mix(diffuse, specular_btdf *
// baseColor, transmission) for the non-metal base, written as a two-term mixture of the
// opaque glTF BRDF and a rough dielectric, so that sample, eval and pdf agree.
#pragma once

#include <variant>

#include "materials/lobes/dielectric.h"
#include "materials/metal_rough_bsdf.h"
#include "materials/lobes/thin_dielectric.h"

namespace penumbra {

class GltfTransmissionBsdf final : public Bsdf {
public:
    // p: the glTF material without transmission; dielectric: the rough dielectric that
    // replaces the share `transmission` (in [0, 1]) of the non-metal base. thin_walled
    // (no KHR_materials_volume): a ThinDielectricBsdf sheet that does not bend what it
    // transmits; else the refracting boundary of a closed volume (DielectricBsdf).
    GltfTransmissionBsdf(const MetalRoughParams& p, float transmission,
                         const DielectricParams& dielectric, bool thin_walled = false);
    Spectrum eval(Vec3 wo, Vec3 wi, Transport mode) const override;
    // The opaque part's diffuse base; the dielectric has no diffuse lobe.
    Spectrum eval_diffuse(Vec3 wo, Vec3 wi, Transport mode) const override;
    float pdf(Vec3 wo, Vec3 wi, Transport mode) const override;
    std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Vec2 u, Transport mode) const override;
    bool has_specular() const override {
        return dielectric().has_specular() || m_opaque.has_specular();
    }

private:
    // metallic M + (1 - M)((1 - t) base + t dielectric) = w_opaque MetalRough(M') + w_d
    // dielectric, with w_d = (1 - M) t and M' = M / w_opaque.
    static MetalRoughParams opaque_params(MetalRoughParams p, float transmission);
    const Bsdf& dielectric() const {
        return std::visit([](const auto& b) -> const Bsdf& { return b; }, m_dielectric);
    }

    float m_weight;  // w_d, also the probability of sampling the dielectric
    MetalRoughBsdf m_opaque;
    std::variant<DielectricBsdf, ThinDielectricBsdf> m_dielectric;
};

}  // namespace penumbra
