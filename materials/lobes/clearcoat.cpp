#include "materials/lobes/clearcoat.h"

#include <algorithm>
#include <cmath>

#include "materials/lobes/fresnel.h"

namespace penumbra {

ClearcoatLobe::ClearcoatLobe(float strength, float alpha, Vec3 normal, MicrofacetType type)
    : m_c(std::clamp(strength, 0.0f, 1.0f)),
      m_delta(alpha < kDeltaAlpha),
      m_frame(Frame::from_normal(normal)),
      m_dist(type, alpha) {
    if (!m_delta) m_albedo = SpecularAlbedo(type, alpha);
}

float ClearcoatLobe::fresnel(float cos_vh) const {
    return fresnel_schlick(Spectrum(kF0), 1, cos_vh).x;
}

float ClearcoatLobe::eval(Vec3 wo, Vec3 wi, Transport mode) const {
    if (m_delta || wo.z <= 0 || wi.z <= 0) return 0;
    const Vec3 o = m_frame.to_local(wo), i = m_frame.to_local(wi);
    if (o.z <= 0 || i.z <= 0) return 0;
    Vec3 h = o + i;
    if (length_squared(h) == 0) return 0;
    h = normalize(h);
    const float f =
        m_c * fresnel(std::max(0.0f, dot(o, h))) * m_dist.D(h) * m_dist.G(o, i) / (4 * o.z * i.z);
    return mode == Transport::Radiance ? f * (i.z / wi.z) : f * (o.z / wo.z);
}

float ClearcoatLobe::pdf(Vec3 wo, Vec3 wi) const {
    if (m_delta || wo.z <= 0 || wi.z <= 0) return 0;
    const Vec3 o = m_frame.to_local(wo), i = m_frame.to_local(wi);
    if (o.z <= 0 || i.z <= 0) return 0;
    const Vec3 h = normalize(o + i);
    const float oh = dot(o, h);
    if (oh <= 0) return 0;
    // Reflection maps h to wi with Jacobian 1 / (4 o.h); the rotation to the base frame
    // keeps solid angles.
    return m_dist.pdf_visible(o, h) / (4 * oh);
}

std::optional<Vec3> ClearcoatLobe::sample(Vec3 wo, Vec2 u) const {
    if (m_delta || wo.z <= 0) return std::nullopt;
    const Vec3 o = m_frame.to_local(wo);
    if (o.z <= 0) return std::nullopt;
    const Vec3 i = reflect(o, m_dist.sample_visible(o, u));
    const Vec3 wi = m_frame.to_world(i);
    if (i.z <= 0 || wi.z <= 0) return std::nullopt;
    return wi;
}

std::optional<Vec3> ClearcoatLobe::mirror(Vec3 wo) const {
    const Vec3 o = m_frame.to_local(wo);
    if (wo.z <= 0 || o.z <= 0) return std::nullopt;
    const Vec3 wi = m_frame.to_world(Vec3(-o.x, -o.y, o.z));
    if (!(wi.z > 0)) return std::nullopt;
    return normalize(wi);
}

float ClearcoatLobe::mirror_reflectance(Vec3 wo) const {
    return m_c * fresnel(std::max(0.0f, dot(wo, m_frame.n)));
}

float ClearcoatLobe::layer_albedo(Vec3 w) const {
    const float mu = std::clamp(std::abs(dot(w, m_frame.n)), 0.0f, 1.0f);
    if (m_delta) return m_c * fresnel(mu);  // a mirror's albedo is its Fresnel
    const Vec2 ab = m_albedo.at(mu);
    return m_c * (kF0 * ab.x + (1 - kF0) * ab.y);
}

}  // namespace penumbra
