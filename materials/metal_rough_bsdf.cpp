#include "materials/metal_rough_bsdf.h"

#include <algorithm>
#include <cmath>

#include "core/sampling/warp.h"
#include "materials/fresnel.h"

namespace penumbra {

MetalRoughBsdf::MetalRoughBsdf(const MetalRoughParams& p)
    : m_p(p),
      m_dist(p.distribution, p.alpha),
      m_delta(p.alpha < kDeltaAlpha),
      m_f0_max(max_component(p.dielectric_f0)) {
    if (m_p.layering != GltfLayering::AlbedoScaled || m_p.metallic >= 1) return;
    float e_avg;
    if (m_delta) {
        // A mirror reflects F(mu) = f0 + (f90 - f0)(1 - mu)^5, whose cosine-weighted
        // average is f0 + (f90 - f0) 2 int (1 - mu)^5 mu dmu = f0 + (f90 - f0) / 21.
        e_avg = m_f0_max + (m_p.dielectric_f90 - m_f0_max) / 21;
    } else {
        m_albedo = SpecularAlbedo(p.distribution, p.alpha);
        const Vec2 avg = m_albedo.average();
        e_avg = m_f0_max * avg.x + (m_p.dielectric_f90 - m_f0_max) * avg.y;
    }
    // E_avg reaches 1 only for a lossless mirror layer (f0 = f90 = 1), which leaves
    // nothing to the base anyway.
    m_base_norm = e_avg < 1 ? 1 / (1 - e_avg) : 0;
}

float MetalRoughBsdf::base_transmittance(float mu) const {
    if (m_p.layering == GltfLayering::Spec || m_delta) {
        // The spec's 1 - F; for a mirror layer this is also 1 - E, its albedo.
        const float w = std::pow(1 - std::clamp(mu, 0.0f, 1.0f), 5.0f);
        return 1 - (m_f0_max + (m_p.dielectric_f90 - m_f0_max) * w);
    }
    const Vec2 ab = m_albedo.at(mu);
    return 1 - (m_f0_max * ab.x + (m_p.dielectric_f90 - m_f0_max) * ab.y);
}

Spectrum MetalRoughBsdf::specular_fresnel(float c) const {
    const Spectrum fd = fresnel_schlick(m_p.dielectric_f0, m_p.dielectric_f90, c);
    const Spectrum fm = fresnel_schlick(m_p.base_color, 1, c);
    return fd * (1 - m_p.metallic) + fm * m_p.metallic;
}

Spectrum MetalRoughBsdf::diffuse_term(float cos_o, float cos_i, float cos_vh) const {
    if (m_p.metallic >= 1) return Spectrum(0);
    float weight;
    if (m_p.layering == GltfLayering::Spec) {
        // glTF's fresnel_mix: the base keeps what the layer transmits at v.h.
        weight = base_transmittance(cos_vh);
    } else {
        // What the layer leaves on the way in and on the way out, normalized so that
        // the base's cosine-weighted average of the second factor is 1.
        weight = base_transmittance(cos_o) * base_transmittance(cos_i) * m_base_norm;
    }
    return m_p.base_color * ((1 - m_p.metallic) * std::max(0.0f, weight) * kInvPi);
}

float MetalRoughBsdf::specular_probability(Vec3 wo) const {
    // Lobe weights from the albedo each lobe would have at normal-ish incidence; any
    // positive choice keeps the estimator unbiased, this one keeps variance low.
    const float spec = luminance(specular_fresnel(wo.z));
    const float diff = m_p.metallic >= 1 ? 0.0f
                                         : luminance(m_p.base_color) * (1 - m_p.metallic) *
                                               std::max(0.0f, base_transmittance(wo.z));
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
    Spectrum f = diffuse_term(wo.z, wi.z, vh);
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
