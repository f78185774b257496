#include "materials/lobes/thin_dielectric.h"

#include <cmath>

#include "materials/lobes/fresnel.h"

namespace penumbra {

namespace {

// The mirror image through the surface plane: where a thin sheet sends a direction that
// it transmits instead of reflecting.
Vec3 mirror(Vec3 w) { return {w.x, w.y, -w.z}; }

float mean(Spectrum s) { return (s.x + s.y + s.z) * (1.0f / 3); }

}  // namespace

// Unlike DielectricBsdf, eta 1 is not forced to a Dirac lobe: a rough sheet blurs what
// it transmits whatever its IOR, as the glTF transmission model says.
ThinDielectricBsdf::ThinDielectricBsdf(const DielectricParams& p)
    : m_p(p),
      m_dist(p.distribution, p.alpha),
      m_delta(p.alpha < kDeltaAlpha),
      m_film(p.iridescence > 0 && p.film.thickness > 0) {}

float ThinDielectricBsdf::sheet_reflectance(float cos_theta, float eta) {
    // Both sides see the sheet from the same medium, so the first interface is always
    // entered from outside; with T = 1 - R the series R + T^2 R / (1 - R^2) is 2R / (1 + R).
    const float R = fresnel_dielectric(std::abs(cos_theta), eta);
    return R < 1 ? 2 * R / (1 + R) : 1.0f;
}

Spectrum ThinDielectricBsdf::reflectance(float cos_theta) const {
    if (!m_film) return Spectrum(sheet_reflectance(cos_theta, m_p.eta));
    // Both faces are entered from outside at the same cosine (parallel faces, one medium
    // around), the film's face at its outside's.
    const float c = std::min(std::abs(cos_theta), 1.0f);
    const float R = fresnel_dielectric(c, m_p.eta);
    const Spectrum R1 = film_interface_reflectance(m_p.film, m_p.iridescence, m_p.eta, c, R);
    Spectrum r;
    for (int i = 0; i < 3; ++i) {
        // The incoherent sum R1 + T1^2 R / (1 - R1 R) with T1 = 1 - R1.
        const float denom = 1 - R1[i] * R;
        r[i] = denom > 0 ? (R1[i] + R - 2 * R1[i] * R) / denom : 1.0f;
    }
    return r;
}

std::optional<ThinDielectricBsdf::Pair> ThinDielectricBsdf::pair(Vec3 wo, Vec3 wi) const {
    if (wo.z == 0 || wi.z == 0) return std::nullopt;
    Pair r;
    r.reflection = wo.z * wi.z > 0;
    r.wr = r.reflection ? wi : mirror(wi);
    const Vec3 h = wo + r.wr;
    if (!(length_squared(h) > 0)) return std::nullopt;
    r.h = normalize(h);
    if (r.h.z < 0) r.h = -r.h;
    r.woh = dot(wo, r.h);
    if (r.woh * wo.z <= 0 || dot(r.wr, r.h) * r.wr.z <= 0) return std::nullopt;
    return r;
}

Spectrum ThinDielectricBsdf::eval(Vec3 wo, Vec3 wi, Transport) const {
    if (m_delta) return Spectrum(0);
    const std::optional<Pair> q = pair(wo, wi);
    if (!q) return Spectrum(0);
    // The mirror lobe D G / (4 |cos_o cos_i|) (Walter et al. 2007, eq. 20), split by F.
    const float lobe = m_dist.D(q->h) * m_dist.G(wo, q->wr, q->h, m_p.masking) /
                       (4 * std::abs(wo.z * wi.z));
    if (m_film) {
        const Spectrum F = reflectance(q->woh);
        return q->reflection ? m_p.reflectance * F * lobe
                             : m_p.transmittance * (Spectrum(1) - F) * lobe;
    }
    const float F = sheet_reflectance(q->woh, m_p.eta);
    return q->reflection ? m_p.reflectance * (F * lobe) : m_p.transmittance * ((1 - F) * lobe);
}

float ThinDielectricBsdf::pdf(Vec3 wo, Vec3 wi, Transport) const {
    if (m_delta) return 0;
    const std::optional<Pair> q = pair(wo, wi);
    if (!q) return 0;
    const float F = m_film ? mean(reflectance(q->woh)) : sheet_reflectance(q->woh, m_p.eta);
    // Mirroring keeps solid angle, so both lobes have the reflection Jacobian (Walter eq. 14).
    const float pdf_h = m_dist.pdf(wo.z > 0 ? wo : -wo, q->h, m_p.masking);
    return (q->reflection ? F : 1 - F) * pdf_h / (4 * std::abs(q->woh));
}

std::optional<BsdfSample> ThinDielectricBsdf::sample(Vec3 wo, float u_lobe, Vec2 u,
                                                     Transport mode) const {
    if (wo.z == 0) return std::nullopt;
    if (m_delta && m_film) {
        const Spectrum Fc = reflectance(wo.z);
        const float F = mean(Fc);
        if (u_lobe < F) {
            const Vec3 wi(-wo.x, -wo.y, wo.z);
            return BsdfSample{wi, m_p.reflectance * Fc / std::abs(wi.z), F, Lobe::Specular, 1};
        }
        return BsdfSample{-wo, m_p.transmittance * (Spectrum(1) - Fc) / std::abs(wo.z), 1 - F,
                          Lobe::Specular, 1};
    }
    if (m_delta) {
        const float F = sheet_reflectance(wo.z, m_p.eta);
        if (u_lobe < F) {
            const Vec3 wi(-wo.x, -wo.y, wo.z);
            return BsdfSample{wi, m_p.reflectance * (F / std::abs(wi.z)), F, Lobe::Specular, 1};
        }
        return BsdfSample{-wo, m_p.transmittance * ((1 - F) / std::abs(wo.z)), 1 - F,
                          Lobe::Specular, 1};
    }
    const Vec3 h = m_dist.sample(wo.z > 0 ? wo : -wo, u, m_p.masking);
    const float woh = dot(wo, h);
    if (woh * wo.z <= 0) return std::nullopt;
    const Vec3 wr = reflect(wo, h);
    if (wr.z * wo.z <= 0) return std::nullopt;
    const float F = m_film ? mean(reflectance(woh)) : sheet_reflectance(woh, m_p.eta);
    const Vec3 wi = u_lobe < F ? wr : mirror(wr);
    const float pdf_value = pdf(wo, wi, mode);
    if (!(pdf_value > 0)) return std::nullopt;
    return BsdfSample{wi, eval(wo, wi, mode), pdf_value, Lobe::Glossy, 1};
}

}  // namespace penumbra
