#include "materials/gltf_transmission_bsdf.h"

#include <algorithm>

namespace penumbra {

MetalRoughParams GltfTransmissionBsdf::opaque_params(MetalRoughParams p, float transmission) {
    const float w_opaque = 1 - (1 - p.metallic) * transmission;
    // With nothing left of the opaque part its parameters do not matter; keep them finite.
    p.metallic = w_opaque > 0 ? std::clamp(p.metallic / w_opaque, 0.0f, 1.0f) : 1.0f;
    return p;
}

GltfTransmissionBsdf::GltfTransmissionBsdf(const MetalRoughParams& p, float transmission,
                                           const DielectricParams& dielectric, bool thin_walled)
    : m_weight(std::clamp((1 - p.metallic) * transmission, 0.0f, 1.0f)),
      m_opaque(opaque_params(p, std::clamp(transmission, 0.0f, 1.0f))),
      m_dielectric(thin_walled ? decltype(m_dielectric)(ThinDielectricBsdf(dielectric))
                               : decltype(m_dielectric)(DielectricBsdf(dielectric))) {}

Spectrum GltfTransmissionBsdf::eval(Vec3 wo, Vec3 wi, Transport mode) const {
    Spectrum f = dielectric().eval(wo, wi, mode) * m_weight;
    if (m_weight < 1) f += m_opaque.eval(wo, wi, mode) * (1 - m_weight);
    return f;
}

Spectrum GltfTransmissionBsdf::eval_diffuse(Vec3 wo, Vec3 wi, Transport mode) const {
    if (!(m_weight < 1)) return Spectrum(0);
    return m_opaque.eval_diffuse(wo, wi, mode) * (1 - m_weight);
}

float GltfTransmissionBsdf::pdf(Vec3 wo, Vec3 wi, Transport mode) const {
    float p = dielectric().pdf(wo, wi, mode) * m_weight;
    if (m_weight < 1) p += m_opaque.pdf(wo, wi, mode) * (1 - m_weight);
    return p;
}

std::optional<BsdfSample> GltfTransmissionBsdf::sample(Vec3 wo, float u_lobe, Vec2 u,
                                                       Transport mode) const {
    // Choose a component with probability equal to its weight, reusing u_lobe inside it.
    const bool pick_dielectric = u_lobe < m_weight;
    const float weight = pick_dielectric ? m_weight : 1 - m_weight;
    const float u_inner = std::min(
        pick_dielectric ? u_lobe / m_weight : (u_lobe - m_weight) / (1 - m_weight), 0x1.fffffep-1f);
    std::optional<BsdfSample> s = pick_dielectric ? dielectric().sample(wo, u_inner, u, mode)
                                             : m_opaque.sample(wo, u_inner, u, mode);
    if (!s) return std::nullopt;
    if (s->is_specular()) {
        // A Dirac lobe of one component: its weight scales f and its choice the pdf.
        s->f *= weight;
        s->pdf *= weight;
        return s;
    }
    s->f = eval(wo, s->wi, mode);
    s->pdf = pdf(wo, s->wi, mode);
    if (!(s->pdf > 0)) return std::nullopt;
    return s;
}

}  // namespace penumbra
