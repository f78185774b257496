#include "materials/albedo/anisotropy_albedo.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <tbb/parallel_for.h>

#include "materials/albedo/specular_albedo.h"
#include "core/math/portable_math.h"

namespace penumbra {

// The grid: alpha = (j / (kAlphas - 1))^4 (at least kAnisotropicMinAlpha), strength
// s = k / (kStrengths - 1), mu = (i / (kMus - 1))^3, phi = (1 - (1 - v)^2) pi / 2 with
// v = l / (kPhis - 1) (D is symmetric in x and in y, so phi folds into [0, pi/2]; the
// nodes crowd towards the smooth axis y, where a stretched lobe's albedo changes fastest:
// there the view sees the grooves head-on, a degree off it their slopes).
struct Grid {
    static constexpr int kAlphas = 16;
    static constexpr int kStrengths = 9;
    static constexpr int kMus = 32;
    static constexpr int kPhis = 13;
};

struct AnisotropyAlbedoTable {
    // (A, B) per alpha row j, strength k, phi l and mu column i.
    std::array<std::array<std::array<std::array<Vec2, Grid::kMus>, Grid::kPhis>, Grid::kStrengths>,
               Grid::kAlphas>
        ab;
    // The cosine-weighted hemispherical average of each (alpha, strength) node's interpolant.
    std::array<std::array<Vec2, Grid::kStrengths>, Grid::kAlphas> average;
};

namespace {

float node_alpha(int j) {
    const float t = j / float(Grid::kAlphas - 1);
    return (t * t) * (t * t);
}
float node_strength(int k) { return k / float(Grid::kStrengths - 1); }
float node_mu(int i) {
    const float s = i / float(Grid::kMus - 1);
    return s * s * s;
}
float node_phi(int l) {
    const float v = 1 - l / float(Grid::kPhis - 1);
    return (1 - v * v) * (0.5f * kPi);
}

// Weights of 2 int mu f(mu) dmu for the interpolant linear in mu between the columns,
// the closed form specular_albedo.cpp uses.
std::array<double, Grid::kMus> mu_weights() {
    std::array<double, Grid::kMus> w{};
    for (int i = 0; i + 1 < Grid::kMus; ++i) {
        const double a = node_mu(i), b = node_mu(i + 1), h = b - a;
        w[i] += (b * (b * b - a * a) - 2.0 / 3 * (b * b * b - a * a * a)) / h;
        w[i + 1] += (2.0 / 3 * (b * b * b - a * a * a) - a * (b * b - a * a)) / h;
    }
    return w;
}

AnisotropyAlbedoTable* build_table(MicrofacetType type) {
    auto* t = new AnisotropyAlbedoTable;
    // Beckmann's visible normals need more angular nodes (as in specular_albedo.cpp), and
    // cost far more each: its table takes about 45 s, GGX's 1.5 s (two busy cores).
    const int n_radial = 16, n_angular = type == MicrofacetType::Beckmann ? 48 : 16;
    tbb::parallel_for(0, Grid::kAlphas * Grid::kStrengths, [&](int jk) {
        const int j = jk / Grid::kStrengths, k = jk % Grid::kStrengths;
        const Vec2 a = anisotropic_alphas(node_alpha(j), node_strength(k));
        const MicrofacetDistribution dist(type, a.x, a.y);
        for (int l = 0; l < Grid::kPhis; ++l)
            for (int i = 0; i < Grid::kMus; ++i) {
                // At mu = 0 the view is tangent; just above it, the limit.
                const float mu = std::max(node_mu(i), 1e-4f);
                const float sin_theta = std::sqrt(1 - mu * mu), phi = node_phi(l);
                const Vec3 wo(sin_theta * portable_cos(phi), sin_theta * portable_sin(phi), mu);
                t->ab[j][k][l][i] = integrate_specular_albedo(dist, wo, n_radial, n_angular);
            }
    });
    // (1/pi) int E cos dw over the hemisphere = (2/pi) int_0^{pi/2} c(phi) dphi with
    // c = 2 int E mu dmu; linear in phi between nodes, so the trapezoid rule is exact.
    const std::array<double, Grid::kMus> wmu = mu_weights();
    std::array<double, Grid::kPhis> wphi{};
    for (int l = 0; l + 1 < Grid::kPhis; ++l) {
        const double h = double(node_phi(l + 1)) - node_phi(l);
        wphi[l] += 0.5 * h * (2 / M_PI);
        wphi[l + 1] += 0.5 * h * (2 / M_PI);
    }
    for (int j = 0; j < Grid::kAlphas; ++j)
        for (int k = 0; k < Grid::kStrengths; ++k) {
            double sa = 0, sb = 0;
            for (int l = 0; l < Grid::kPhis; ++l)
                for (int i = 0; i < Grid::kMus; ++i) {
                    sa += wphi[l] * wmu[i] * t->ab[j][k][l][i].x;
                    sb += wphi[l] * wmu[i] * t->ab[j][k][l][i].y;
                }
            t->average[j][k] = Vec2(float(sa), float(sb));
        }
    return t;
}

const AnisotropyAlbedoTable& table(MicrofacetType type) {
    // Built on first use, once per process (thread-safe statics); never freed.
    if (type == MicrofacetType::Beckmann) {
        static const AnisotropyAlbedoTable* beckmann = build_table(MicrofacetType::Beckmann);
        return *beckmann;
    }
    static const AnisotropyAlbedoTable* ggx = build_table(MicrofacetType::Ggx);
    return *ggx;
}

// Cell and position of x in [0, n - 1].
void locate(float x, int n, int& i, float& f) {
    x = std::clamp(x, 0.0f, float(n - 1));
    i = std::min(static_cast<int>(x), n - 2);
    f = x - i;
}

}  // namespace

Vec2 anisotropic_alphas(float alpha, float strength) {
    // KHR_materials_anisotropy: alpha_t = mix(alpha, 1, strength^2), alpha_b = alpha.
    const float s = std::clamp(strength, 0.0f, 1.0f);
    const float a = std::clamp(alpha, 0.0f, 1.0f);
    const float at = a + (1 - a) * (s * s);
    return {std::max(at, kAnisotropicMinAlpha), std::max(a, kAnisotropicMinAlpha)};
}

AnisotropicSpecularAlbedo::AnisotropicSpecularAlbedo(MicrofacetType type, float alpha,
                                                     float strength)
    : m_table(&table(type)) {
    locate(std::sqrt(std::sqrt(std::clamp(alpha, 0.0f, 1.0f))) * (Grid::kAlphas - 1),
           Grid::kAlphas, m_j, m_fj);
    locate(std::clamp(strength, 0.0f, 1.0f) * (Grid::kStrengths - 1), Grid::kStrengths, m_k, m_fk);
    const auto& avg = m_table->average;
    const Vec2 a0 = avg[m_j][m_k] * (1 - m_fk) + avg[m_j][m_k + 1] * m_fk;
    const Vec2 a1 = avg[m_j + 1][m_k] * (1 - m_fk) + avg[m_j + 1][m_k + 1] * m_fk;
    m_average = a0 * (1 - m_fj) + a1 * m_fj;
}

int AnisotropicSpecularAlbedo::columns() { return Grid::kMus; }

Vec2 AnisotropicSpecularAlbedo::azimuthal_average(int i) const {
    // The trapezoid rule over the phi nodes, exact for the interpolant linear in phi.
    Vec2 sum(0, 0);
    for (int l = 0; l < Grid::kPhis; ++l) {
        const float lo = l > 0 ? node_phi(l - 1) : node_phi(0);
        const float hi = l + 1 < Grid::kPhis ? node_phi(l + 1) : node_phi(l);
        const float w = 0.5f * (hi - lo) / (0.5f * kPi);
        const auto node = [&](int j, int k) { return m_table->ab[j][k][l][i]; };
        const Vec2 c0 = node(m_j, m_k) * (1 - m_fk) + node(m_j, m_k + 1) * m_fk;
        const Vec2 c1 = node(m_j + 1, m_k) * (1 - m_fk) + node(m_j + 1, m_k + 1) * m_fk;
        sum = sum + (c0 * (1 - m_fj) + c1 * m_fj) * w;
    }
    return sum;
}

Vec2 AnisotropicSpecularAlbedo::at(Vec3 w) const {
    const float mu = std::clamp(w.z, 0.0f, 1.0f);
    // Linear in mu (not in cbrt(mu)) and in phi between nodes: average() integrates
    // exactly this interpolant.
    const int i = std::min(static_cast<int>(std::cbrt(mu) * (Grid::kMus - 1)), Grid::kMus - 2);
    const float mu0 = node_mu(i), mu1 = node_mu(i + 1);
    const float fi = std::clamp((mu - mu0) / (mu1 - mu0), 0.0f, 1.0f);
    // Linear in phi between the nodes: invert node_phi for the cell, then interpolate.
    const float phi = std::atan2(std::abs(w.y), std::abs(w.x));
    const float v = 1 - std::sqrt(std::max(0.0f, 1 - phi / (0.5f * kPi)));
    const int l = std::clamp(static_cast<int>(v * (Grid::kPhis - 1)), 0, Grid::kPhis - 2);
    const float phi0 = node_phi(l), phi1 = node_phi(l + 1);
    const float fl = std::clamp((phi - phi0) / (phi1 - phi0), 0.0f, 1.0f);
    const auto corner = [&](int j, int k) {
        const auto& rows = m_table->ab[j][k];
        const Vec2 v0 = rows[l][i] * (1 - fi) + rows[l][i + 1] * fi;
        const Vec2 v1 = rows[l + 1][i] * (1 - fi) + rows[l + 1][i + 1] * fi;
        return v0 * (1 - fl) + v1 * fl;
    };
    const Vec2 c0 = corner(m_j, m_k) * (1 - m_fk) + corner(m_j, m_k + 1) * m_fk;
    const Vec2 c1 = corner(m_j + 1, m_k) * (1 - m_fk) + corner(m_j + 1, m_k + 1) * m_fk;
    return c0 * (1 - m_fj) + c1 * m_fj;
}

}  // namespace penumbra
