#include "materials/albedo/specular_albedo.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "materials/albedo/specular_albedo_table.h"

namespace penumbra {

namespace {

constexpr int kColumns = SpecularAlbedoTable::M;

// The columns' mu, as specular_albedo_column_mu gives them (evaluated by the compiler
// with the same float operations): a load where the function divides.
struct ColumnMu {
    float mu[kColumns];
};
constexpr ColumnMu make_column_mu() {
    ColumnMu c{};
    for (int i = 0; i < kColumns; ++i) c.mu[i] = specular_albedo_column_mu(i);
    return c;
}
constexpr ColumnMu kColumnMu = make_column_mu();

// Guide table over mu: entry k is the largest column i <= M - 2 with mu(i) <= k / kGuide,
// so for mu in [k / kGuide, (k + 1) / kGuide) the column below mu is at or after it:
// 6 columns after in the first entry, where the columns crowd towards mu = 0, 2 in the
// third, and at most 1 in every other.
constexpr int kGuide = 1024;
struct ColumnGuide {
    unsigned char first[kGuide];
};
constexpr ColumnGuide make_column_guide() {
    ColumnGuide g{};
    int i = 0;
    for (int k = 0; k < kGuide; ++k) {
        const float mu = float(k) / kGuide;  // exact: kGuide is a power of two
        while (i < kColumns - 2 && kColumnMu.mu[i + 1] <= mu) ++i;
        g.first[k] = static_cast<unsigned char>(i);
    }
    return g;
}
constexpr ColumnGuide kColumnGuide = make_column_guide();

}  // namespace

// From the guide table, then exact comparisons with the columns, so the result is what floor() of
// the exact cube root would give, without the cost of a cube root, or of the division in a
// bit-level guess with a Newton step, at every lookup.
int specular_albedo_column_below(float mu) {
    if (!(mu > 0)) return 0;
    int i = kColumnGuide.first[std::min(static_cast<int>(mu * kGuide), kGuide - 1)];
    while (i < kColumns - 2 && kColumnMu.mu[i + 1] <= mu) ++i;
    return i;
}

SpecularAlbedo::SpecularAlbedo(MicrofacetType type, float alpha) {
    const float t =
        std::sqrt(std::sqrt(std::clamp(alpha, 0.0f, 1.0f))) * (SpecularAlbedoTable::R - 1);
    m_row = std::min(static_cast<int>(t), SpecularAlbedoTable::R - 2);
    m_frac = t - m_row;
    // Integrated when penumbra is built (albedo_generator.cpp): nothing to
    // compute at start-up or on first use, which saves about 5% of a short render, and
    // 0.1 s of CPU on a scene whose textures use every roughness (FlightHelmet).
    m_table = type == MicrofacetType::Beckmann ? &kSpecularAlbedoBeckmann : &kSpecularAlbedoGgx;
    const float* p0 = m_table->average[m_row];
    const float* p1 = m_table->average[m_row + 1];
    const Vec2 a0(p0[0], p0[1]), a1(p1[0], p1[1]);
    m_average = a0 * (1 - m_frac) + a1 * m_frac;
}

Vec2 SpecularAlbedo::at(float mu) const {
    mu = std::clamp(mu, 0.0f, 1.0f);
    const int i = specular_albedo_column_below(mu);
    // Linear in mu between columns (not in cbrt(mu)): the averages above integrate
    // exactly this interpolant.
    const float mu0 = kColumnMu.mu[i], mu1 = kColumnMu.mu[i + 1];
    const float t = std::clamp((mu - mu0) / (mu1 - mu0), 0.0f, 1.0f);
    const auto& r0 = m_table->ab[m_row];
    const auto& r1 = m_table->ab[m_row + 1];
    const Vec2 v0 = Vec2(r0[i][0], r0[i][1]) * (1 - t) + Vec2(r0[i + 1][0], r0[i + 1][1]) * t;
    const Vec2 v1 = Vec2(r1[i][0], r1[i][1]) * (1 - t) + Vec2(r1[i + 1][0], r1[i + 1][1]) * t;
    return v0 * (1 - m_frac) + v1 * m_frac;
}

}  // namespace penumbra
