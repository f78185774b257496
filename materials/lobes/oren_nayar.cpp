#include "materials/lobes/oren_nayar.h"

#include <algorithm>
#include <cmath>

#include "core/sampling/warp.h"

namespace penumbra {

OrenNayarBsdf::OrenNayarBsdf(Spectrum reflectance, float sigma) : m_R(reflectance) {
    const float s2 = sigma * sigma;
    m_A = 1 - s2 / (2 * (s2 + 0.33f));
    m_B = 0.45f * s2 / (s2 + 0.09f);
    // The model's directional albedo grows with theta_o, from A at normal incidence to
    // A + B/2 at grazing (the B term integrates to B/2 there). Below sigma ~ 0.33 that
    // exceeds 1 (by up to 1.5%): scale A and B so it never does; sigma 0 stays Lambert.
    const float scale = 1 / std::max(1.0f, m_A + 0.5f * m_B);
    m_A *= scale;
    m_B *= scale;
}

Spectrum OrenNayarBsdf::eval(Vec3 wo, Vec3 wi, Transport) const {
    if (wo.z <= 0 || wi.z <= 0) return Spectrum(0);
    const float sin_o = std::sqrt(wo.x * wo.x + wo.y * wo.y);
    const float sin_i = std::sqrt(wi.x * wi.x + wi.y * wi.y);
    float g = 0;
    if (m_B > 0 && sin_o > 1e-6f && sin_i > 1e-6f) {
        // max(0, cos(phi_i - phi_o)) sin(alpha) tan(beta), alpha = max(theta_i, theta_o)
        // and beta = min: the larger angle has the smaller cosine.
        const float cos_dphi = std::max(0.0f, (wi.x * wo.x + wi.y * wo.y) / (sin_i * sin_o));
        const float sin_alpha = wi.z < wo.z ? sin_i : sin_o;
        const float tan_beta = wi.z < wo.z ? sin_o / wo.z : sin_i / wi.z;
        g = cos_dphi * sin_alpha * tan_beta;
    }
    return m_R * (kInvPi * (m_A + m_B * g));
}

float OrenNayarBsdf::pdf(Vec3 wo, Vec3 wi, Transport) const {
    if (wo.z <= 0 || wi.z <= 0) return 0;
    return cosine_hemisphere_pdf(wi);
}

std::optional<BsdfSample> OrenNayarBsdf::sample(Vec3 wo, float, Vec2 u, Transport mode) const {
    if (wo.z <= 0) return std::nullopt;
    const Vec3 wi = square_to_cosine_hemisphere(u);
    const float pdf_value = pdf(wo, wi, mode);
    if (!(pdf_value > 0)) return std::nullopt;
    return BsdfSample{wi, eval(wo, wi, mode), pdf_value, Lobe::Diffuse, 1};
}

}  // namespace penumbra
