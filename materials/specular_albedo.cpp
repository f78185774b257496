#include "materials/specular_albedo.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <mutex>
#include <vector>

#include "core/math/gauss_legendre.h"

namespace penumbra {

struct SpecularAlbedoTable {
    static constexpr int R = SpecularAlbedoGrid::kRows;
    static constexpr int M = SpecularAlbedoGrid::kColumns;
    explicit SpecularAlbedoTable(MicrofacetType t) : type(t) {}
    MicrofacetType type;
    std::array<std::array<Vec2, M>, R> ab;  // (A, B) per roughness row and mu column
    std::array<Vec2, R> average;            // 2 int (A, B) mu dmu of each row's interpolant
    std::array<std::once_flag, R> built;    // rows are integrated on first use
};

namespace {

float column_mu(int i) {
    const float s = i / float(SpecularAlbedoGrid::kColumns - 1);
    return s * s * s;
}

float row_alpha(int j) {
    const float t = j / float(SpecularAlbedoGrid::kRows - 1);
    return (t * t) * (t * t);
}

// Exact 2 int mu f(mu) dmu of the piecewise-linear interpolant through the columns.
Vec2 cosine_average(const std::array<Vec2, SpecularAlbedoTable::M>& row) {
    Vec2 sum(0, 0);
    for (int i = 0; i + 1 < SpecularAlbedoTable::M; ++i) {
        const double a = column_mu(i), b = column_mu(i + 1), h = b - a;
        // int_a^b 2 mu (fa (b - mu) + fb (mu - a)) / h dmu, in closed form.
        const double wa = (b * (b * b - a * a) - 2.0 / 3 * (b * b * b - a * a * a)) / h;
        const double wb = (2.0 / 3 * (b * b * b - a * a * a) - a * (b * b - a * a)) / h;
        sum.x += float(wa * row[i].x + wb * row[i + 1].x);
        sum.y += float(wa * row[i].y + wb * row[i + 1].y);
    }
    return sum;
}

void build_row(SpecularAlbedoTable& t, int j) {
    // Beckmann's visible normals need more angular nodes for the same accuracy
    // (tests/materials/specular_albedo_test.cpp measures both).
    const int n_angular = t.type == MicrofacetType::Beckmann ? 96 : 32;
    const float alpha = row_alpha(j);
    for (int i = 0; i < SpecularAlbedoTable::M; ++i) {
        const float mu = column_mu(i);
        if (j == 0) {
            // The mirror: all light reflects, at v.h = mu.
            t.ab[j][i] = Vec2(1, std::pow(1 - mu, 5.0f));
        } else {
            t.ab[j][i] = integrate_specular_albedo(t.type, alpha, mu, 32, n_angular);
        }
    }
    t.average[j] = cosine_average(t.ab[j]);
}

// The table with rows j and j + 1 built. A scene uses a few roughness values, so rows
// are integrated when first asked for (about 1 ms each for GGX) rather than the whole
// table at start-up (64 rows, 5% of a short render's profile in issue 14).
const SpecularAlbedoTable& table(MicrofacetType type, int j) {
    static SpecularAlbedoTable ggx(MicrofacetType::Ggx), beckmann(MicrofacetType::Beckmann);
    SpecularAlbedoTable& t = type == MicrofacetType::Beckmann ? beckmann : ggx;
    for (int r : {j, j + 1}) std::call_once(t.built[r], [&] { build_row(t, r); });
    return t;
}

// The largest i <= M - 2 with column_mu(i) <= mu, for mu in [0, 1], without a cube root
// call (9% of the profile): a bit-level first guess of cbrt(mu) (Kahan's
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
    while (i > 0 && column_mu(i) > mu) --i;
    while (i < M - 2 && column_mu(i + 1) <= mu) ++i;
    return i;
}

}  // namespace

Vec2 integrate_specular_albedo(MicrofacetType type, float alpha, float mu, int n_radial,
                               int n_angular) {
    // At mu = 0 the view is tangent and the lobe sees nothing; just above, the limit.
    mu = std::clamp(mu, 1e-4f, 1.0f);
    const Vec3 wo(std::sqrt(1 - mu * mu), 0, mu);
    return integrate_specular_albedo(MicrofacetDistribution(type, alpha), wo, n_radial, n_angular);
}

Vec2 integrate_specular_albedo(const MicrofacetDistribution& dist, Vec3 wo, int n_radial,
                               int n_angular) {
    // Visible normals have density G1(wo) (wo.h) D(h) / wo.z; the reflected direction's
    // estimator of f cos / pdf is then G(wo, wi) / G1(wo) times Fresnel. The sample
    // square's first coordinate is radial: the distribution's far tail (grazing wi,
    // where G falls to 0) is squeezed against u.x = 1, so u.x = 1 - (1 - s)^2 spreads
    // it out and Gauss-Legendre in s integrates the now smooth integrand; the second
    // coordinate is an angle, where the midpoint rule of a periodic function converges
    // fast. (Plain 48 x 48 midpoints were off by up to 0.009.)
    std::vector<double> xs, ws;
    gauss_legendre(n_radial, xs, ws);
    const float g1 = dist.G1(wo);
    double a = 0, b = 0;
    for (int y = 0; y < n_angular; ++y)
        for (int x = 0; x < n_radial; ++x) {
            const double s = xs[x];
            const double weight = 2 * (1 - s) * ws[x];  // d(u.x)/ds times the node's weight
            const Vec2 u(float(1 - (1 - s) * (1 - s)), (y + 0.5f) / n_angular);
            const Vec3 h = dist.sample_visible(wo, u);
            const float woh = dot(wo, h);
            if (!(woh > 0)) continue;
            const Vec3 wi = h * (2 * woh) - wo;
            if (wi.z <= 0) continue;
            const double w = weight * dist.G(wo, wi) / g1;
            a += w;
            b += w * std::pow(1.0 - woh, 5.0);
        }
    return Vec2(float(a / n_angular), float(b / n_angular));
}

SpecularAlbedo::SpecularAlbedo(MicrofacetType type, float alpha) {
    const float t = std::sqrt(std::sqrt(std::clamp(alpha, 0.0f, 1.0f))) * (SpecularAlbedoTable::R - 1);
    m_row = std::min(static_cast<int>(t), SpecularAlbedoTable::R - 2);
    m_frac = t - m_row;
    m_table = &table(type, m_row);
    const Vec2 a0 = m_table->average[m_row], a1 = m_table->average[m_row + 1];
    m_average = a0 * (1 - m_frac) + a1 * m_frac;
}

Vec2 SpecularAlbedo::at(float mu) const {
    mu = std::clamp(mu, 0.0f, 1.0f);
    const int i = column_below(mu);
    // Linear in mu between columns (not in cbrt(mu)): the averages above integrate
    // exactly this interpolant.
    const float mu0 = column_mu(i), mu1 = column_mu(i + 1);
    const float t = std::clamp((mu - mu0) / (mu1 - mu0), 0.0f, 1.0f);
    const auto& r0 = m_table->ab[m_row];
    const auto& r1 = m_table->ab[m_row + 1];
    const Vec2 v0 = r0[i] * (1 - t) + r0[i + 1] * t;
    const Vec2 v1 = r1[i] * (1 - t) + r1[i + 1] * t;
    return v0 * (1 - m_frac) + v1 * m_frac;
}

}  // namespace penumbra
