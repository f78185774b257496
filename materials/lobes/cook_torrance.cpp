#include "materials/lobes/cook_torrance.h"

namespace penumbra {

CookTorranceBsdf::CookTorranceBsdf(const CookTorranceParams& p)
    : m_p(p), m_dist(p.distribution, p.alpha), m_delta(p.alpha < kDeltaAlpha) {}

std::optional<Vec3> CookTorranceBsdf::half_vector(Vec3 wo, Vec3 wi) {
    if (wo.z <= 0 || wi.z <= 0) return std::nullopt;
    const Vec3 h = wo + wi;
    if (length_squared(h) == 0) return std::nullopt;
    return normalize(h);
}

Spectrum CookTorranceBsdf::eval(Vec3 wo, Vec3 wi, Transport) const {
    if (m_delta) return Spectrum(0);
    const std::optional<Vec3> h = half_vector(wo, wi);
    if (!h) return Spectrum(0);
    const float woh = dot(wo, *h);
    const float dg = m_dist.D(*h) * m_dist.G(wo, wi, *h, m_p.masking);
    return m_p.scale * m_p.fresnel.eval(woh) * (dg / (4 * wo.z * wi.z));
}

float CookTorranceBsdf::pdf(Vec3 wo, Vec3 wi, Transport) const {
    if (m_delta) return 0;
    const std::optional<Vec3> h = half_vector(wo, wi);
    if (!h) return 0;
    // Reflection maps h to wi with Jacobian 1 / (4 wo.h) (Walter et al. 2007, eq. 14).
    return m_dist.pdf(wo, *h, m_p.masking) / (4 * dot(wo, *h));
}

std::optional<BsdfSample> CookTorranceBsdf::sample(Vec3 wo, float, Vec2 u, Transport mode) const {
    if (wo.z <= 0) return std::nullopt;
    if (m_delta) {
        const Vec3 wi(-wo.x, -wo.y, wo.z);
        return BsdfSample{wi, m_p.scale * m_p.fresnel.eval(wo.z) / wo.z, 1, Lobe::Specular, 1};
    }
    const Vec3 h = m_dist.sample(wo, u, m_p.masking);
    // D sampling (V-cavity) can pick facets that face away from wo: no reflection there.
    if (dot(wo, h) <= 0) return std::nullopt;
    const Vec3 wi = reflect(wo, h);
    if (wi.z <= 0) return std::nullopt;
    const float pdf_value = pdf(wo, wi, mode);
    if (!(pdf_value > 0)) return std::nullopt;
    return BsdfSample{wi, eval(wo, wi, mode), pdf_value, Lobe::Glossy, 1};
}

}  // namespace penumbra
