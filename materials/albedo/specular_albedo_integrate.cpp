// Numerical integration of the specular albedo A, B (specular_albedo.h): for the
// table the build generates, and for tests.
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/math/gauss_legendre.h"
#include "materials/albedo/specular_albedo_table.h"

namespace penumbra {

namespace {

// Exact 2 int mu f(mu) dmu of the piecewise-linear interpolant through the columns.
void cosine_average(const float (&row)[SpecularAlbedoTable::M][2], float (&sum)[2]) {
    sum[0] = sum[1] = 0;
    for (int i = 0; i + 1 < SpecularAlbedoTable::M; ++i) {
        const double a = specular_albedo_column_mu(i), b = specular_albedo_column_mu(i + 1);
        const double h = b - a;
        // int_a^b 2 mu (fa (b - mu) + fb (mu - a)) / h dmu, in closed form.
        const double wa = (b * (b * b - a * a) - 2.0 / 3 * (b * b * b - a * a * a)) / h;
        const double wb = (2.0 / 3 * (b * b * b - a * a * a) - a * (b * b - a * a)) / h;
        for (int c = 0; c < 2; ++c) sum[c] += float(wa * row[i][c] + wb * row[i + 1][c]);
    }
}

}  // namespace

void integrate_specular_albedo_row(MicrofacetType type, int j, SpecularAlbedoTable& t) {
    // Beckmann's visible normals need more angular nodes for the same accuracy
    // (tests/materials/albedo/specular_albedo_test.cpp measures both).
    const int n_angular = type == MicrofacetType::Beckmann ? 96 : 32;
    const float alpha = specular_albedo_row_alpha(j);
    for (int i = 0; i < SpecularAlbedoTable::M; ++i) {
        const float mu = specular_albedo_column_mu(i);
        Vec2 v;
        if (j == 0) {
            // The mirror: all light reflects, at v.h = mu.
            v = Vec2(1, std::pow(1 - mu, 5.0f));
        } else {
            v = integrate_specular_albedo(type, alpha, mu, 32, n_angular);
        }
        t.ab[j][i][0] = v.x;
        t.ab[j][i][1] = v.y;
    }
    cosine_average(t.ab[j], t.average[j]);
}

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

}  // namespace penumbra
