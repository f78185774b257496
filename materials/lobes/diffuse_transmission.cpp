#include "materials/lobes/diffuse_transmission.h"

#include <algorithm>
#include <cmath>

#include "core/sampling/warp.h"

namespace penumbra {

SpecularLayerTransmittance::SpecularLayerTransmittance(const MetalRoughParams& p)
    : m_layering(p.layering),
      m_delta(p.alpha < MetalRoughBsdf::kDeltaAlpha),
      m_f0(max_component(p.dielectric_f0)),
      m_f90(p.dielectric_f90) {
    if (m_layering != GltfLayering::AlbedoScaled) return;
    float e_avg;
    if (m_delta) {
        e_avg = m_f0 + (m_f90 - m_f0) / 21;  // 2 int F(mu) mu dmu of Schlick's curve
    } else {
        m_albedo = SpecularAlbedo(p.distribution, p.alpha);
        const Vec2 avg = m_albedo.average();
        e_avg = m_f0 * avg.x + (m_f90 - m_f0) * avg.y;
    }
    m_norm = e_avg < 1 ? 1 / (1 - e_avg) : 0;
}

float SpecularLayerTransmittance::at(float mu) const {
    mu = std::clamp(mu, 0.0f, 1.0f);
    if (m_layering == GltfLayering::Spec || m_delta)
        return 1 - (m_f0 + (m_f90 - m_f0) * std::pow(1 - mu, 5.0f));
    const Vec2 ab = m_albedo.at(mu);
    return 1 - (m_f0 * ab.x + (m_f90 - m_f0) * ab.y);
}

float SpecularLayerTransmittance::weight(Vec3 wo, Vec3 wi) const {
    float w;
    if (m_layering == GltfLayering::Spec) {
        const Vec3 mirrored(wi.x, wi.y, std::copysign(wi.z, wo.z));
        Vec3 h = wo + mirrored;
        if (length_squared(h) == 0) return 0;
        h = normalize(h);
        w = at(std::abs(dot(wo, h)));
    } else {
        w = at(std::abs(wo.z)) * at(std::abs(wi.z)) * m_norm;
    }
    return std::max(0.0f, w);
}

Spectrum DiffuseTransmissionLobe::eval(Vec3 wo, Vec3 wi) const {
    if (!(wo.z * wi.z < 0)) return Spectrum(0);
    return m_color * (m_layer.weight(wo, wi) * kInvPi);
}

float DiffuseTransmissionLobe::pdf(Vec3 wo, Vec3 wi) const {
    if (!(wo.z * wi.z < 0)) return 0;
    return std::abs(wi.z) * kInvPi;
}

std::optional<Vec3> DiffuseTransmissionLobe::sample(Vec3 wo, Vec2 u) const {
    if (wo.z == 0) return std::nullopt;
    Vec3 wi = square_to_cosine_hemisphere(u);
    if (wi.z <= 0) return std::nullopt;
    if (wo.z > 0) wi.z = -wi.z;
    return wi;
}

}  // namespace penumbra
