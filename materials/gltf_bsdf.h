// The glTF material as a stack of lobes: an optional clearcoat over an optional sheen
// over the core model (MetalRoughBsdf, GltfTransmissionBsdf or
// GltfDiffuseTransmissionBsdf). The one place that decides the layers' albedo scaling
// and the probabilities of sampling each.
#pragma once

#include <optional>
#include <variant>

#include "materials/lobes/clearcoat.h"
#include "materials/gltf_diffuse_transmission_bsdf.h"
#include "materials/gltf_transmission_bsdf.h"
#include "materials/metal_rough_bsdf.h"
#include "materials/lobes/sheen.h"

namespace penumbra {

// f(wo, wi) = f_coat + S_coat (f_sheen + S_sheen f_core), with
//     S_coat  = min(1 - c E_c(wo), 1 - c E_c(wi)),
//     S_sheen = min(1 - max3(sheenColor) E_s(wo), 1 - max3(sheenColor) E_s(wi)),
// E_c the coat's directional albedo with its Fresnel (specular_albedo.h, in the coat's
// frame), E_s the sheen lobe's (sheen_albedo.h), cosines taken as |cos| so that light
// transmitted to the far side is scaled alike. This is KHR_materials_sheen's albedo
// scaling, used for the coat too instead of the clearcoat spec's 1 - c F(v.h) (which,
// like the base's fresnel_mix, gains energy at grazing angles): reciprocal, and a lobe
// with albedo a under a layer of albedo E reflects at most E(wo) + (1 - E(wo)) a <= 1.
// The min() loses a little energy where E(wo) != E(wi) (Estevez & Kulla 2017, sec. 4).
// --gltf-layering changes only the core's diffuse base (and the diffuse transmission
// lobe under it); the coat and sheen are albedo-scaled in both.
// In local shading coordinates (z = base shading normal); no cosine in eval.
class GltfBsdf final : public Bsdf {
public:
    using Core = std::variant<MetalRoughBsdf, GltfTransmissionBsdf, GltfDiffuseTransmissionBsdf>;

    GltfBsdf(const Core& core, const std::optional<SheenLobe>& sheen,
             const std::optional<ClearcoatLobe>& coat);
    Spectrum eval(Vec3 wo, Vec3 wi, Transport mode) const override;
    // The core's diffuse part, seen through the sheen and the coat as eval sees it.
    Spectrum eval_diffuse(Vec3 wo, Vec3 wi, Transport mode) const override;
    float pdf(Vec3 wo, Vec3 wi, Transport mode) const override;
    // eval and pdf in one pass: the core's own eval_pdf (MetalRoughBsdf shares its half
    // vector, D(h) and wo's terms), the same values bit for bit.
    Spectrum eval_pdf(Vec3 wo, Vec3 wi, Transport mode, float* pdf_out) const override;
    std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Vec2 u, Transport mode) const override;
    bool has_specular() const override;

private:
    struct Choice {
        float coat = 0, sheen = 0, core = 1;  // probabilities, sum 1
    };
    const Bsdf& core() const;
    float coat_scale(Vec3 wo, Vec3 wi) const;
    float sheen_scale(Vec3 wo, Vec3 wi) const;
    float sheen_layer_albedo(Vec3 w) const;  // max3(color) E_s(|cos|)
    // From each layer's albedo at wo and what reaches the core; wo-only, so the pdf is
    // a fixed mixture.
    Choice choose(Vec3 wo) const;

    Core m_core;
    std::optional<SheenLobe> m_sheen;
    float m_sheen_max = 0;  // max3(sheenColor)
    std::optional<ClearcoatLobe> m_coat;
};

}  // namespace penumbra
