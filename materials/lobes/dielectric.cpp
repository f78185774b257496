#include "materials/lobes/dielectric.h"

#include <cmath>

#include "core/error.h"
#include "materials/lobes/fresnel.h"

namespace penumbra {

namespace {

float sqr(float x) { return x * x; }

float mean(Spectrum s) { return (s.x + s.y + s.z) * (1.0f / 3); }

}  // namespace

// An index-matched interface (eta 1) passes light straight through: a Dirac lobe whatever
// the roughness (the refracted half vector degenerates).
DielectricBsdf::DielectricBsdf(const DielectricParams& p)
    : m_p(p),
      m_dist(p.distribution, p.alpha),
      m_delta(p.alpha < kDeltaAlpha || p.eta == 1),
      m_film(p.iridescence > 0 && p.film.thickness > 0) {
    CHECK(p.masking != MaskingModel::VCavity, "the V-cavity masking has no transmission");
    CHECK(p.eta > 0);
}

std::optional<DielectricBsdf::Pair> DielectricBsdf::pair(Vec3 wo, Vec3 wi) const {
    if (wo.z == 0 || wi.z == 0) return std::nullopt;
    Pair r;
    r.reflection = wo.z * wi.z > 0;
    r.etap = wo.z > 0 ? m_p.eta : 1 / m_p.eta;
    // The generalized half vector, h ~ eta_o wo + eta_i wi (Walter et al. 2007, eq. 16),
    // formed from the upper and lower direction so that swapping wo and wi gives the
    // same float h.
    Vec3 h = wo + wi;
    if (!r.reflection) h = wo.z > 0 ? wo + wi * m_p.eta : wi + wo * m_p.eta;
    if (!(length_squared(h) > 0)) return std::nullopt;
    r.h = normalize(h);
    if (r.h.z < 0) r.h = -r.h;
    r.woh = dot(wo, r.h);
    r.wih = dot(wi, r.h);
    // Each direction must lie on its own side of the microfacet too.
    if (r.woh * wo.z <= 0 || r.wih * wi.z <= 0) return std::nullopt;
    // Fresnel where it is well conditioned: near the critical angle, F seen from the
    // dense side has an infinite slope, so refraction takes the cosine on the less dense
    // side (equal by Stokes' relations), reflection the symmetric mean of its two.
    float cos_f = 0.5f * (r.woh + r.wih);
    if (!r.reflection) cos_f = (m_p.eta >= 1) == (wo.z > 0) ? r.woh : r.wih;
    r.F = fresnel_dielectric(cos_f, m_p.eta);
    if (m_film) {
        // The film's cosine: refraction takes the direction on the film's side.
        if (!r.reflection) cos_f = (wo.z > 0) == m_p.film_above ? r.woh : r.wih;
        r.Fc = film_fresnel(cos_f, r.F);
        r.F = mean(r.Fc);
    }
    return r;
}

Spectrum DielectricBsdf::film_fresnel(float cos_h, float F) const {
    // Total internal reflection at the interface: the film cannot pass what it meets.
    if (F >= 1) return Spectrum(1);
    // The IOR beyond the film over that of its outside.
    const float eta = m_p.film_above ? m_p.eta : 1 / m_p.eta;
    float cos_outside = std::abs(cos_h);
    if ((cos_h > 0) != m_p.film_above) {
        cos_outside = film_outside_cos(cos_h, eta);
        if (cos_outside < 0) return Spectrum(1);
    }
    return film_interface_reflectance(m_p.film, m_p.iridescence, eta, cos_outside, F);
}

Spectrum DielectricBsdf::eval(Vec3 wo, Vec3 wi, Transport mode) const {
    if (m_delta) return Spectrum(0);
    const std::optional<Pair> q = pair(wo, wi);
    if (!q) return Spectrum(0);
    const float F = q->F;
    const float dg = m_dist.D(q->h) * m_dist.G(wo, wi, q->h, m_p.masking);
    const float cos_oi = std::abs(wo.z * wi.z);
    if (m_film) {
        if (q->reflection) return m_p.reflectance * q->Fc * (dg / (4 * cos_oi));
        float ft = dg * std::abs(q->wih * q->woh) / (cos_oi * sqr(q->wih + q->woh / q->etap));
        if (mode == Transport::Radiance) ft /= sqr(q->etap);
        return m_p.transmittance * (Spectrum(1) - q->Fc) * ft;
    }
    if (q->reflection) return m_p.reflectance * (F * dg / (4 * cos_oi));
    // Walter et al. 2007, eq. 21, in the form divided by eta_i^2 and times the Radiance
    // factor 1 / etap^2 (so eta_o^2 in the numerator for radiance, as there).
    const float denom = sqr(q->wih + q->woh / q->etap);
    float ft = (1 - F) * dg * std::abs(q->wih * q->woh) / (cos_oi * denom);
    if (mode == Transport::Radiance) ft /= sqr(q->etap);
    return m_p.transmittance * ft;
}

float DielectricBsdf::pdf(Vec3 wo, Vec3 wi, Transport) const {
    if (m_delta) return 0;
    const std::optional<Pair> q = pair(wo, wi);
    if (!q) return 0;
    // Visible normals as seen from wo's side; reflection or refraction with probability
    // F or 1 - F.
    const float pdf_h = m_dist.pdf(wo.z > 0 ? wo : -wo, q->h, m_p.masking);
    const float F = q->F;
    if (q->reflection) return F * pdf_h / (4 * std::abs(q->woh));  // Walter eq. 14
    // The Jacobian of the refracted half vector (Walter eq. 17, divided through by eta_i^2).
    const float dh_dwi = std::abs(q->wih) / sqr(q->wih + q->woh / q->etap);
    return (1 - F) * pdf_h * dh_dwi;
}

std::optional<BsdfSample> DielectricBsdf::sample_smooth(Vec3 wo, float u_lobe,
                                                        Transport mode) const {
    if (m_film) return sample_smooth_film(wo, u_lobe, mode);
    // Index-matched: no interface at all, straight through. (Fresnel and Snell in float
    // would call a grazing wo, cos below ~2e-4, totally reflected: 1 - cos^2 rounds to 1.)
    if (m_p.eta == 1) return BsdfSample{-wo, m_p.transmittance / std::abs(wo.z), 1,
                                        Lobe::Specular, 1};
    const float F = fresnel_dielectric(wo.z, m_p.eta);
    if (u_lobe < F) {
        const Vec3 wi(-wo.x, -wo.y, wo.z);
        return BsdfSample{wi, m_p.reflectance * (F / std::abs(wi.z)), F, Lobe::Specular, 1};
    }
    const float etap = wo.z > 0 ? m_p.eta : 1 / m_p.eta;
    const std::optional<Vec3> wi = refract(wo, Vec3(0, 0, wo.z > 0 ? 1.0f : -1.0f), etap);
    if (!wi || wi->z == 0) return std::nullopt;
    float ft = (1 - F) / std::abs(wi->z);
    if (mode == Transport::Radiance) ft /= sqr(etap);
    return BsdfSample{*wi, m_p.transmittance * ft, 1 - F, Lobe::Specular, etap};
}

std::optional<BsdfSample> DielectricBsdf::sample_smooth_film(Vec3 wo, float u_lobe,
                                                             Transport mode) const {
    const Spectrum Fc = film_fresnel(wo.z, fresnel_dielectric(wo.z, m_p.eta));
    const float F = mean(Fc);
    if (u_lobe < F) {
        const Vec3 wi(-wo.x, -wo.y, wo.z);
        return BsdfSample{wi, m_p.reflectance * Fc / std::abs(wi.z), F, Lobe::Specular, 1};
    }
    // Index-matched: straight through what the film does not reflect (see sample_smooth).
    if (m_p.eta == 1)
        return BsdfSample{-wo, m_p.transmittance * (Spectrum(1) - Fc) / std::abs(wo.z), 1 - F,
                          Lobe::Specular, 1};
    const float etap = wo.z > 0 ? m_p.eta : 1 / m_p.eta;
    const std::optional<Vec3> wi = refract(wo, Vec3(0, 0, wo.z > 0 ? 1.0f : -1.0f), etap);
    if (!wi || wi->z == 0) return std::nullopt;
    float ft = 1 / std::abs(wi->z);
    if (mode == Transport::Radiance) ft /= sqr(etap);
    return BsdfSample{*wi, m_p.transmittance * (Spectrum(1) - Fc) * ft, 1 - F, Lobe::Specular,
                      etap};
}

std::optional<BsdfSample> DielectricBsdf::sample(Vec3 wo, float u_lobe, Vec2 u,
                                                 Transport mode) const {
    if (wo.z == 0) return std::nullopt;
    if (m_delta) return sample_smooth(wo, u_lobe, mode);
    const Vec3 wo_up = wo.z > 0 ? wo : -wo;
    const Vec3 h = m_dist.sample(wo_up, u, m_p.masking);
    const float woh = dot(wo, h);
    if (woh * wo.z <= 0) return std::nullopt;
    float F = fresnel_dielectric(woh, m_p.eta);
    if (m_film) F = mean(film_fresnel(woh, F));
    std::optional<Vec3> wi;
    float eta = 1;
    if (u_lobe < F) {
        wi = reflect(wo, h);
        if (wi->z * wo.z <= 0) return std::nullopt;
    } else {
        eta = wo.z > 0 ? m_p.eta : 1 / m_p.eta;
        wi = refract(wo, woh > 0 ? h : -h, eta);
        if (!wi || wi->z * wo.z >= 0) return std::nullopt;
    }
    const float pdf_value = pdf(wo, *wi, mode);
    if (!(pdf_value > 0)) return std::nullopt;
    return BsdfSample{*wi, eval(wo, *wi, mode), pdf_value, Lobe::Glossy, eta};
}

}  // namespace penumbra
