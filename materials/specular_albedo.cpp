#include "materials/specular_albedo.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "materials/specular_albedo_table.h"

namespace penumbra {

namespace {

// The largest i <= M - 2 with column mu(i) <= mu, for mu in [0, 1], without a cube
// root call (9% of the profile): a bit-level first guess of cbrt(mu) (Kahan's
// exponent division), one Newton step (relative error below 2e-3, under 0.2 columns),
// and then exact comparisons with the columns, so the result is what floor() of the
// exact cube root would give.
int column_below(float mu) {
    constexpr int M = SpecularAlbedoTable::M;
    if (!(mu > 0)) return 0;
    uint32_t bits;
    std::memcpy(&bits, &mu, 4);
    bits = bits / 3 + 709921077u;
    float c;
    std::memcpy(&c, &bits, 4);
    c = c - (c * c * c - mu) / (3 * c * c);
    int i = std::clamp(static_cast<int>(c * (M - 1)), 0, M - 2);
    while (i > 0 && specular_albedo_column_mu(i) > mu) --i;
    while (i < M - 2 && specular_albedo_column_mu(i + 1) <= mu) ++i;
    return i;
}

}  // namespace

SpecularAlbedo::SpecularAlbedo(MicrofacetType type, float alpha) {
    const float t = std::sqrt(std::sqrt(std::clamp(alpha, 0.0f, 1.0f))) * (SpecularAlbedoTable::R - 1);
    m_row = std::min(static_cast<int>(t), SpecularAlbedoTable::R - 2);
    m_frac = t - m_row;
    // Integrated when penumbra was built (specular_albedo_generator.cpp): nothing to
    // compute at start-up or on first use (issue 14 measured 5% of a short render's
    // profile for building it at start-up, and lazily by row it still cost FlightHelmet,
    // whose textures use every roughness, 0.1 s of CPU).
    m_table = type == MicrofacetType::Beckmann ? &kSpecularAlbedoBeckmann : &kSpecularAlbedoGgx;
    const float* p0 = m_table->average[m_row];
    const float* p1 = m_table->average[m_row + 1];
    const Vec2 a0(p0[0], p0[1]), a1(p1[0], p1[1]);
    m_average = a0 * (1 - m_frac) + a1 * m_frac;
}

Vec2 SpecularAlbedo::at(float mu) const {
    mu = std::clamp(mu, 0.0f, 1.0f);
    const int i = column_below(mu);
    // Linear in mu between columns (not in cbrt(mu)): the averages above integrate
    // exactly this interpolant.
    const float mu0 = specular_albedo_column_mu(i), mu1 = specular_albedo_column_mu(i + 1);
    const float t = std::clamp((mu - mu0) / (mu1 - mu0), 0.0f, 1.0f);
    const auto& r0 = m_table->ab[m_row];
    const auto& r1 = m_table->ab[m_row + 1];
    const Vec2 v0 = Vec2(r0[i][0], r0[i][1]) * (1 - t) + Vec2(r0[i + 1][0], r0[i + 1][1]) * t;
    const Vec2 v1 = Vec2(r1[i][0], r1[i][1]) * (1 - t) + Vec2(r1[i + 1][0], r1[i + 1][1]) * t;
    return v0 * (1 - m_frac) + v1 * m_frac;
}

}  // namespace penumbra
