#include "materials/metal_rough_bsdf.h"

#include "core/sampling/warp.h"
#include "materials/fresnel.h"

namespace penumbra {

MetalRoughBsdf::MetalRoughBsdf(const MetalRoughParams& p)
    : m_p(p), m_dist(p.distribution, p.alpha), m_delta(p.alpha < kDeltaAlpha) {}

Spectrum MetalRoughBsdf::specular_fresnel(float c) const {
    const Spectrum fd = fresnel_schlick(m_p.dielectric_f0, m_p.dielectric_f90, c);
    const Spectrum fm = fresnel_schlick(m_p.base_color, 1, c);
    return fd * (1 - m_p.metallic) + fm * m_p.metallic;
}

Spectrum MetalRoughBsdf::diffuse_term(float cos_vh) const {
    // glTF's fresnel_mix: the diffuse base keeps what the dielectric layer transmits.
    const Spectrum fd = fresnel_schlick(m_p.dielectric_f0, m_p.dielectric_f90, cos_vh);
    return m_p.base_color * ((1 - m_p.metallic) * (1 - max_component(fd)) * kInvPi);
}

float MetalRoughBsdf::specular_probability(Vec3 wo) const {
    // Lobe weights from the albedo each lobe would have at normal-ish incidence; any
    // positive choice keeps the estimator unbiased, this one keeps variance low.
    const float spec = luminance(specular_fresnel(wo.z));
    const float diff = luminance(diffuse_term(wo.z)) * kPi;
    const float total = spec + diff;
    if (!(total > 0)) return 0;
    return std::clamp(spec / total, 0.0f, 1.0f);
}

Spectrum MetalRoughBsdf::eval(Vec3 wo, Vec3 wi, Transport) const {
    if (wo.z <= 0 || wi.z <= 0) return Spectrum(0);
    Vec3 h = wo + wi;
    if (length_squared(h) == 0) return Spectrum(0);
    h = normalize(h);
    const float vh = std::max(0.0f, dot(wo, h));
    Spectrum f = diffuse_term(vh);
    if (!m_delta) {
        const float spec = m_dist.D(h) * m_dist.G(wo, wi) / (4 * wo.z * wi.z);
        f += specular_fresnel(vh) * spec;
    }
    return f;
}

float MetalRoughBsdf::pdf_specular(Vec3 wo, Vec3 wi) const {
    if (m_delta) return 0;
    const Vec3 h = normalize(wo + wi);
    const float woh = dot(wo, h);
    if (woh <= 0) return 0;
    // Reflection maps h to wi with Jacobian 1 / (4 |wo.h|).
    return m_dist.pdf_visible(wo, h) / (4 * woh);
}

float MetalRoughBsdf::pdf(Vec3 wo, Vec3 wi, Transport) const {
    if (wo.z <= 0 || wi.z <= 0) return 0;
    const float ps = specular_probability(wo);
    return ps * pdf_specular(wo, wi) + (1 - ps) * cosine_hemisphere_pdf(wi);
}

std::optional<BsdfSample> MetalRoughBsdf::sample(Vec3 wo, float u_lobe, Vec2 u,
                                                 Transport mode) const {
    if (wo.z <= 0) return std::nullopt;
    const float ps = specular_probability(wo);
    if (u_lobe < ps) {
        if (m_delta) {
            const Vec3 wi(-wo.x, -wo.y, wo.z);
            // f * cos / pdf must equal F / ps: f = F / cos, pdf = ps.
            return BsdfSample{wi, specular_fresnel(wo.z) / wi.z, ps, Lobe::Specular, 1};
        }
        const Vec3 h = m_dist.sample_visible(wo, u);
        const Vec3 wi = reflect(wo, h);
        if (wi.z <= 0) return std::nullopt;
        const float pdf_value = pdf(wo, wi, mode);
        if (!(pdf_value > 0)) return std::nullopt;
        return BsdfSample{wi, eval(wo, wi, mode), pdf_value, Lobe::Glossy, 1};
    }
    const Vec3 wi = square_to_cosine_hemisphere(u);
    if (wi.z <= 0) return std::nullopt;
    const float pdf_value = pdf(wo, wi, mode);
    if (!(pdf_value > 0)) return std::nullopt;
    return BsdfSample{wi, eval(wo, wi, mode), pdf_value, Lobe::Diffuse, 1};
}

}  // namespace penumbra
