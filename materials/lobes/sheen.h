// KHR_materials_sheen's lobe: the "Charlie" distribution and visibility of Estevez &
// Kulla 2017 ("Production Friendly Microfacet Sheen BRDF"), f = color D(h) V(wo, wi), with
// no Fresnel, as the extension's implementation notes write it. Reflection only.
#pragma once

#include "materials/bsdf.h"

namespace penumbra {

// The lobe's shape for one sheen roughness r in [0, 1]. The spec sets alpha_g = r (not
// r^2, unlike the glTF Sample Viewer's shaders). r is clamped to kMinRoughness: below
// it the fitted Lambda lets the lobe reflect more than it receives at grazing views
// (quadrature: max over mu of E is 1.04 at r 0.06, 1.10 at 0.05, 2.1 at 0.01, 6.1 at
// 0.001; 0.989 at 0.07), which the albedo scaling cannot make up for.
class CharlieSheen {
public:
    static constexpr float kMinRoughness = 0.07f;
    static constexpr float kMinCos = 1e-4f;  // see value()
    explicit CharlieSheen(float roughness);
    float roughness() const { return m_r; }
    // D(h) = (2 + 1/r) sin(theta_h)^(1/r) / (2 pi); h in the upper hemisphere.
    float D(Vec3 h) const;
    // Lambda(cos theta) from the paper's fitted curve, mirrored about cos 0.5 (eq. 3-4).
    float lambda(float cos_theta) const;
    // D V with V = 1 / ((1 + Lambda(wo) + Lambda(wi)) 4 cos_o cos_i), cosines clamped to
    // kMinCos; 0 unless both are above the horizon. No cosine.
    float value(Vec3 wo, Vec3 wi) const;

private:
    float m_r;
    float m_inv_r;
    float m_a, m_b, m_c, m_d, m_e;  // the fit's coefficients at this roughness
};

// The lobe with its colour: f = color D V, sampled uniformly over the hemisphere (the
// lobe is broad and does not vanish towards grazing wi, where a cosine warp would
// starve it: per sample, the albedo estimate's relative standard deviation is 0.2-1.4
// this way against 0.5-3.2 cosine-weighted, over r 0.07-1 and cos_o 1-0.01). Local
// shading frame, wo and wi away from the surface.
class SheenLobe {
public:
    SheenLobe(Spectrum color, float roughness) : m_color(color), m_sheen(roughness) {}
    Spectrum eval(Vec3 wo, Vec3 wi) const;
    float pdf(Vec3 wo, Vec3 wi) const;
    // Direction only; the caller evaluates the composed BSDF there.
    std::optional<Vec3> sample(Vec3 wo, Vec2 u) const;
    const CharlieSheen& shape() const { return m_sheen; }
    Spectrum color() const { return m_color; }

private:
    Spectrum m_color;
    CharlieSheen m_sheen;
};

}  // namespace penumbra
