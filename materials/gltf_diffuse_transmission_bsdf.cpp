#include "materials/gltf_diffuse_transmission_bsdf.h"

#include <algorithm>
#include <cmath>

#include "materials/lobes/fresnel.h"

namespace penumbra {

MetalRoughParams GltfDiffuseTransmissionBsdf::with_metallic(MetalRoughParams p, float metallic,
                                                            float base_scale) {
    p.metallic = metallic;
    p.base_color = p.base_color * base_scale;
    return p;
}

GltfDiffuseTransmissionBsdf::GltfDiffuseTransmissionBsdf(const MetalRoughParams& p,
                                                         const DiffuseTransmissionParams& dt,
                                                         float transmission,
                                                         const DielectricParams& dielectric,
                                                         bool thin_walled)
    : m_opaque_base(p.base_color * (1 - std::clamp(dt.factor, 0.0f, 1.0f))),
      m_f0_max(max_component(p.dielectric_f0)),
      m_f90(p.dielectric_f90),
      m_metal(with_metallic(p, 1, 1)),
      m_opaque(with_metallic(p, 0, 1 - std::clamp(dt.factor, 0.0f, 1.0f))),
      m_dt(dt.color * std::clamp(dt.factor, 0.0f, 1.0f), SpecularLayerTransmittance(p)),
      m_glass(thin_walled ? decltype(m_glass)(ThinDielectricBsdf(dielectric))
                          : decltype(m_glass)(DielectricBsdf(dielectric))) {
    const float metallic = std::clamp(p.metallic, 0.0f, 1.0f);
    const float t = std::clamp(transmission, 0.0f, 1.0f);
    m_w[kMetal] = metallic;
    m_w[kOpaque] = m_w[kDiffuseTransmission] = (1 - metallic) * (1 - t);
    m_w[kGlass] = (1 - metallic) * t;
}

bool GltfDiffuseTransmissionBsdf::has_specular() const {
    return (m_w[kMetal] > 0 && m_metal.has_specular()) ||
           (m_w[kOpaque] > 0 && m_opaque.has_specular()) ||
           (m_w[kGlass] > 0 && glass().has_specular());
}

void GltfDiffuseTransmissionBsdf::probabilities(Vec3 wo, float q[kCount]) const {
    // Rough albedo guesses at wo: the metal and the glass reflect or pass about all, the
    // opaque part its Fresnel plus its diffuse share, the transmission lobe its colour
    // through the layer. Any positive choice is unbiased; these keep variance low.
    const float mu = std::abs(wo.z);
    const float layer = m_dt.layer().at(mu);
    const float fresnel = m_f0_max + (m_f90 - m_f0_max) * std::pow(1 - std::min(mu, 1.0f), 5.0f);
    const float h[kCount] = {1, fresnel + luminance(m_opaque_base) * layer,
                             luminance(m_dt.color()) * layer, 1};
    float total = 0;
    for (int c = 0; c < kCount; ++c) total += q[c] = m_w[c] * std::max(0.0f, h[c]);
    for (int c = 0; c < kCount; ++c) q[c] = total > 0 ? q[c] / total : (c == kOpaque ? 1 : 0);
}

Spectrum GltfDiffuseTransmissionBsdf::eval_component(int c, Vec3 wo, Vec3 wi,
                                                     Transport mode) const {
    switch (c) {
        case kMetal:
            return m_metal.eval(wo, wi, mode);
        case kOpaque:
            return m_opaque.eval(wo, wi, mode);
        case kDiffuseTransmission:
            return m_dt.eval(wo, wi);
        default:
            return glass().eval(wo, wi, mode);
    }
}

float GltfDiffuseTransmissionBsdf::pdf_component(int c, Vec3 wo, Vec3 wi, Transport mode) const {
    switch (c) {
        case kMetal:
            return m_metal.pdf(wo, wi, mode);
        case kOpaque:
            return m_opaque.pdf(wo, wi, mode);
        case kDiffuseTransmission:
            return m_dt.pdf(wo, wi);
        default:
            return glass().pdf(wo, wi, mode);
    }
}

Spectrum GltfDiffuseTransmissionBsdf::eval(Vec3 wo, Vec3 wi, Transport mode) const {
    Spectrum f(0);
    for (int c = 0; c < kCount; ++c)
        if (m_w[c] > 0) f += eval_component(c, wo, wi, mode) * m_w[c];
    return f;
}

Spectrum GltfDiffuseTransmissionBsdf::eval_diffuse(Vec3 wo, Vec3 wi, Transport mode) const {
    Spectrum f(0);
    if (m_w[kOpaque] > 0) f += m_opaque.eval_diffuse(wo, wi, mode) * m_w[kOpaque];
    if (m_w[kDiffuseTransmission] > 0) f += m_dt.eval(wo, wi) * m_w[kDiffuseTransmission];
    return f;
}

float GltfDiffuseTransmissionBsdf::pdf(Vec3 wo, Vec3 wi, Transport mode) const {
    float q[kCount];
    probabilities(wo, q);
    float p = 0;
    for (int c = 0; c < kCount; ++c)
        if (q[c] > 0) p += q[c] * pdf_component(c, wo, wi, mode);
    return p;
}

std::optional<BsdfSample> GltfDiffuseTransmissionBsdf::sample(Vec3 wo, float u_lobe, Vec2 u,
                                                              Transport mode) const {
    float q[kCount];
    probabilities(wo, q);
    int c = 0;
    float lo = 0;
    while (c + 1 < kCount && (q[c] == 0 || u_lobe >= lo + q[c])) lo += q[c++];
    if (!(q[c] > 0)) return std::nullopt;
    const float u_inner = std::clamp((u_lobe - lo) / q[c], 0.0f, 0x1.fffffep-1f);
    std::optional<BsdfSample> s;
    if (c == kDiffuseTransmission) {
        const std::optional<Vec3> wi = m_dt.sample(wo, u);
        if (wi) s = BsdfSample{*wi, Spectrum(0), 0, Lobe::Diffuse, 1};
    } else {
        s = c == kMetal    ? m_metal.sample(wo, u_inner, u, mode)
            : c == kOpaque ? m_opaque.sample(wo, u_inner, u, mode)
                           : glass().sample(wo, u_inner, u, mode);
    }
    if (!s) return std::nullopt;
    if (s->is_specular()) {
        // A Dirac lobe of one component: its weight scales f and its choice the pdf.
        s->f *= m_w[c];
        s->pdf *= q[c];
        return s;
    }
    s->f = eval(wo, s->wi, mode);
    s->pdf = pdf(wo, s->wi, mode);
    if (!(s->pdf > 0)) return std::nullopt;
    return s;
}

}  // namespace penumbra
