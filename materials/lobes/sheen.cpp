#include "materials/lobes/sheen.h"

#include <algorithm>
#include <cmath>

#include "core/sampling/warp.h"

namespace penumbra {

namespace {
float mix(float a, float b, float t) { return a + (b - a) * t; }
}  // namespace

CharlieSheen::CharlieSheen(float roughness)
    : m_r(std::clamp(roughness, kMinRoughness, 1.0f)), m_inv_r(1 / m_r) {
    // Estevez & Kulla 2017, table 1: the fit at r = 1 and r = 0, blended in (1 - r)^2
    // (the extension's l(x, alphaG)).
    const float t = (1 - m_r) * (1 - m_r);
    m_a = mix(21.5473f, 25.3245f, t);
    m_b = mix(3.82987f, 3.32435f, t);
    m_c = mix(0.19823f, 0.16801f, t);
    m_d = mix(-1.97760f, -1.27393f, t);
    m_e = mix(-4.32054f, -4.85967f, t);
}

float CharlieSheen::D(Vec3 h) const {
    // sin^2 from x and y: 1 - cos^2 cancels near the normal.
    const float sin2 = std::min(1.0f, h.x * h.x + h.y * h.y);
    return (2 + m_inv_r) * std::pow(sin2, 0.5f * m_inv_r) * (0.5f * kInvPi);
}

float CharlieSheen::lambda(float cos_theta) const {
    const auto l = [&](float x) { return m_a / (1 + m_b * std::pow(x, m_c)) + m_d * x + m_e; };
    const float c = std::abs(cos_theta);
    return c < 0.5f ? std::exp(l(c)) : std::exp(2 * l(0.5f) - l(1 - c));
}

float CharlieSheen::value(Vec3 wo, Vec3 wi) const {
    if (wo.z <= 0 || wi.z <= 0) return 0;
    Vec3 h = wo + wi;
    if (length_squared(h) == 0) return 0;
    h = normalize(h);
    // Cosines below kMinCos are taken as kMinCos in V: as cos_o -> 0, Lambda tends to a
    // constant, so 1 / (Lambda 4 cos_o) and with it the albedo diverge (E reaches 1.2 at
    // cos_o 1e-6 and 2.4 at 1e-7 for r 0.07). Clamped, E stays below its value at 1e-4
    // (< 0.9). Symmetric in wo and wi, so still reciprocal.
    const float co = std::max(wo.z, kMinCos), ci = std::max(wi.z, kMinCos);
    const float v = 1 / ((1 + lambda(co) + lambda(ci)) * 4 * co * ci);
    return D(h) * v;
}

Spectrum SheenLobe::eval(Vec3 wo, Vec3 wi) const { return m_color * m_sheen.value(wo, wi); }

float SheenLobe::pdf(Vec3 wo, Vec3 wi) const { return wo.z > 0 && wi.z > 0 ? kInv2Pi : 0.0f; }

std::optional<Vec3> SheenLobe::sample(Vec3 wo, Vec2 u) const {
    if (wo.z <= 0) return std::nullopt;
    const Vec3 wi = square_to_uniform_hemisphere(u);
    if (wi.z <= 0) return std::nullopt;
    return wi;
}

}  // namespace penumbra
