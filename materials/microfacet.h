// The microfacet distribution shared by all rough models: GGX / Trowbridge-Reitz with
// Smith masking (Walter et al. 2007; Heitz 2014) and visible-normal sampling (Heitz
// 2018). Local frame, z = macro normal; alpha is the (isotropic) roughness parameter.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/math/vec.h"

namespace penumbra {

class GgxDistribution {
public:
    explicit GgxDistribution(float alpha) : m_alpha(std::max(alpha, 1e-7f)) {}
    float alpha() const { return m_alpha; }

    // Normal distribution D(h), normalized so that the integral of D(h) cos(theta_h)
    // over the hemisphere is 1.
    float D(Vec3 h) const {
        const float cos2 = h.z * h.z;
        if (cos2 <= 0) return 0;
        const float a2 = m_alpha * m_alpha;
        const float denom = cos2 * (a2 - 1) + 1;
        return a2 / (kPi * denom * denom);
    }
    // Smith's Lambda(w).
    float lambda(Vec3 w) const {
        const float cos2 = w.z * w.z;
        if (cos2 <= 0) return 0;
        const float tan2 = std::max(0.0f, 1 - cos2) / cos2;
        return 0.5f * (-1 + std::sqrt(1 + m_alpha * m_alpha * tan2));
    }
    float G1(Vec3 w) const { return 1 / (1 + lambda(w)); }
    // Height-correlated masking-shadowing (Heitz 2014, eq. 99).
    float G(Vec3 wo, Vec3 wi) const { return 1 / (1 + lambda(wo) + lambda(wi)); }

    // Density of visible normals seen from wo (wo.z > 0): G1(wo) max(0, wo.h) D(h) / wo.z.
    float pdf_visible(Vec3 wo, Vec3 h) const {
        const float woh = dot(wo, h);
        if (woh <= 0 || wo.z <= 0) return 0;
        return G1(wo) * woh * D(h) / wo.z;
    }
    // Samples a visible normal for wo (wo.z > 0), Heitz 2018 ("Sampling the GGX
    // Distribution of Visible Normals", listing 1).
    Vec3 sample_visible(Vec3 wo, Vec2 u) const {
        const Vec3 vh = normalize(Vec3(m_alpha * wo.x, m_alpha * wo.y, wo.z));
        const float lensq = vh.x * vh.x + vh.y * vh.y;
        const Vec3 t1 = lensq > 0 ? Vec3(-vh.y, vh.x, 0) / std::sqrt(lensq) : Vec3(1, 0, 0);
        const Vec3 t2 = cross(vh, t1);
        const float r = std::sqrt(u.x), phi = 2 * kPi * u.y;
        const float p1 = r * std::cos(phi);
        const float s = 0.5f * (1 + vh.z);
        const float p2 = (1 - s) * std::sqrt(std::max(0.0f, 1 - p1 * p1)) + s * r * std::sin(phi);
        const Vec3 nh = t1 * p1 + t2 * p2 + vh * std::sqrt(std::max(0.0f, 1 - p1 * p1 - p2 * p2));
        return normalize(Vec3(m_alpha * nh.x, m_alpha * nh.y, std::max(1e-6f, nh.z)));
    }

private:
    float m_alpha;
};

}  // namespace penumbra
