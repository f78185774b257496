// Anisotropic GGX and Beckmann of materials/lobes/microfacet.h: normalization of D, Lambda
// against the projected area it stands for, visible-normal sampling against its pdf
// (including grazing and very unequal alphas), D sampling, and the isotropic case equal
// to the one-alpha distribution.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "materials/lobes/microfacet.h"
#include "support/bsdf/bsdf_checks.h"
#include "support/bsdf/bsdf_properties.h"
#include "support/statistics/chi2.h"
#include "support/statistics/quadrature.h"

namespace penumbra {
namespace {

using test::spherical_direction;

const MicrofacetType kTypes[] = {MicrofacetType::Ggx, MicrofacetType::Beckmann};
// (alpha_x, alpha_y): KHR_materials_anisotropy's alpha_t = mix(alpha, 1, s^2) along x
// and alpha_b = alpha along y, from mild to a 100:1 line-like lobe.
const Vec2 kAlphas[] = {{0.3f, 0.1f}, {0.1f, 0.5f}, {1.0f, 0.04f}, {1.0f, 0.01f}, {0.64f, 0.25f}};

std::string describe(MicrofacetType type, Vec2 a, Vec3 wo = Vec3(0, 0, 1)) {
    std::ostringstream s;
    s << (type == MicrofacetType::Ggx ? "GGX" : "Beckmann") << " alpha (" << a.x << ", " << a.y
      << "), wo (" << wo.x << ", " << wo.y << ", " << wo.z << ")";
    return s.str();
}

// Integral of f(h) over the hemisphere, in (theta, phi).
template <typename F>
double integrate_hemisphere(F f, double tol = 1e-7) {
    return test::integrate_2d(
        [&](double theta, double phi) {
            const Vec3 h(float(std::sin(theta) * std::cos(phi)),
                         float(std::sin(theta) * std::sin(phi)), float(std::cos(theta)));
            return f(h) * std::sin(theta);
        },
        0, M_PI / 2, 0, 2 * M_PI, tol);
}

TEST(AnisotropicMicrofacet, ProjectedAreaIsNormalized) {
    // int D(h) cos(theta_h) dh = 1: a D off by a constant (ax ay against alpha^2) or
    // with its axes swapped in one place only fails by far more than 1e-4.
    for (MicrofacetType type : kTypes)
        for (Vec2 a : kAlphas) {
            const MicrofacetDistribution d(type, a.x, a.y);
            const double integral = integrate_hemisphere([&](Vec3 h) { return d.D(h) * h.z; });
            EXPECT_NEAR(integral, 1.0, 1e-4) << describe(type, a);
        }
}

TEST(AnisotropicMicrofacet, LambdaIsTheProjectedArea) {
    // Smith: cos(theta_o) (1 + Lambda(wo)) = int max(0, wo.h) D(h) dh (Heitz 2014, eq. 2
    // with G1 = 1 / (1 + Lambda)). With D checked above this tests Lambda independently,
    // at azimuths between the axes and near grazing, where the projected roughness
    // sqrt(ax^2 cos^2 + ay^2 sin^2) matters most. The integral runs over the stretched
    // slopes h = normalize(ax tan(b) cos(p), ay tan(b) sin(p), 1), b in [0, pi/2), where
    // a 100:1 lobe is round (in (theta, phi) its ridge along phi = 0 defeats the
    // quadrature); d omega_h = ax ay cos^3(theta_h) / cos^3(b) sin(b) db dp.
    for (MicrofacetType type : kTypes)
        for (Vec2 a : kAlphas)
            for (float cos_o : {0.9f, 0.5f, 0.1f, 0.02f})
                for (float phi : {0.0f, 0.7f, 1.5707964f, 2.4f}) {
                    const MicrofacetDistribution d(type, a.x, a.y);
                    const Vec3 wo = spherical_direction(cos_o, phi);
                    const double area = test::integrate_2d(
                        [&](double b, double p) {
                            const double t = std::tan(b);
                            const Vec3 h = normalize(Vec3(float(a.x * t * std::cos(p)),
                                                          float(a.y * t * std::sin(p)), 1));
                            const double cb = std::cos(b);
                            const double jacobian =
                                double(a.x) * a.y * h.z * h.z * h.z * std::sin(b) / (cb * cb * cb);
                            return std::max(0.0f, dot(wo, h)) * d.D(h) * jacobian;
                        },
                        0, M_PI / 2, 0, 2 * M_PI, 1e-9);
                    const double expected = wo.z * (1 + d.lambda(wo));
                    EXPECT_NEAR(area / expected, 1.0, 2e-4) << describe(type, a, wo);
                }
}

TEST(AnisotropicMicrofacet, IsotropicAlphasGiveTheIsotropicDistribution) {
    // Two equal alphas take the one-alpha expressions: bitwise the same values.
    Rng rng(3);
    for (MicrofacetType type : kTypes)
        for (float alpha : {1e-3f, 0.09f, 0.5f, 1.0f}) {
            const MicrofacetDistribution iso(type, alpha), two(type, alpha, alpha);
            for (int i = 0; i < 200; ++i) {
                const Vec3 w = test::random_direction(rng), h = test::random_direction(rng);
                const Vec2 u(rng.next_float(), rng.next_float());
                EXPECT_EQ(iso.D(h), two.D(h));
                EXPECT_EQ(iso.lambda(w), two.lambda(w));
                EXPECT_EQ(iso.pdf_visible(w, h), two.pdf_visible(w, h));
                EXPECT_EQ(iso.sample_visible(w, u), two.sample_visible(w, u));
                EXPECT_EQ(iso.sample_D(u), two.sample_D(u));
            }
        }
}

TEST(AnisotropicMicrofacet, NearlyIsotropicAlphasAreContinuous) {
    // The anisotropic branch at alpha_y one float above alpha agrees with the isotropic
    // one to float rounding: the two formulas describe the same surface.
    Rng rng(4);
    for (MicrofacetType type : kTypes)
        for (float alpha : {0.05f, 0.3f, 1.0f}) {
            const MicrofacetDistribution iso(type, alpha),
                two(type, alpha, std::nextafter(alpha, 2.0f));
            for (int i = 0; i < 200; ++i) {
                const Vec3 w = test::random_direction(rng), h = test::random_direction(rng);
                EXPECT_NEAR(two.D(h), iso.D(h), 1e-4f * iso.D(h) + 1e-30f);
                EXPECT_NEAR(two.lambda(w), iso.lambda(w), 1e-4f * iso.lambda(w) + 1e-7f);
            }
        }
}

TEST(AnisotropicMicrofacet, VisibleNormalsAreNormalized) {
    for (MicrofacetType type : kTypes)
        for (Vec2 a : kAlphas)
            for (float cos_o : {1.0f, 0.5f, 0.05f}) {
                const MicrofacetDistribution d(type, a.x, a.y);
                const Vec3 wo = spherical_direction(cos_o, 0.9f);
                const double integral =
                    integrate_hemisphere([&](Vec3 h) { return d.pdf_visible(wo, h); });
                EXPECT_NEAR(integral, 1.0, 2e-4) << describe(type, a, wo);
            }
}

TEST(AnisotropicMicrofacet, VisibleNormalSamplesFollowTheirPdf) {
    // The lobes here are at least 0.1 wide along one axis, which the 10 x 20 hemisphere
    // cells resolve; the narrow axis (0.01) is covered through the BSDF's half-vector
    // test (metal_rough_anisotropy_test.cpp).
    const Vec2 alphas[] = {{0.3f, 0.1f}, {0.1f, 0.5f}, {1.0f, 0.04f}, {0.64f, 0.25f}};
    const float cos_os[] = {1.0f, 0.5f, 0.05f};
    const float phis[] = {0.0f, 0.8f, 1.5707964f};
    const int tests = 2 * std::size(alphas) * std::size(cos_os) * std::size(phis);
    const double level = test::sidak_significance(0.01, tests);
    int seed = 30;
    for (MicrofacetType type : kTypes)
        for (Vec2 a : alphas)
            for (float cos_o : cos_os)
                for (float phi : phis) {
                    const MicrofacetDistribution d(type, a.x, a.y);
                    const Vec3 wo = spherical_direction(cos_o, phi);
                    test::SphereChi2Options o;
                    o.hemisphere = true;
                    o.samples = 100000;
                    o.seed = ++seed;
                    o.significance = level;
                    const test::Chi2Result r = test::chi2_sphere(
                        [&](Rng& rng) {
                            return std::optional<Vec3>(
                                d.sample_visible(wo, {rng.next_float(), rng.next_float()}));
                        },
                        [&](Vec3 h) { return double(d.pdf_visible(wo, h)); }, o);
                    EXPECT_TRUE(r.passed) << describe(type, a, wo) << "\n" << r.report;
                }
}

TEST(AnisotropicMicrofacet, DSamplesFollowDCos) {
    const Vec2 alphas[] = {{0.3f, 0.1f}, {1.0f, 0.04f}};
    const double level = test::sidak_significance(0.01, 4);
    for (MicrofacetType type : kTypes)
        for (Vec2 a : alphas) {
            const MicrofacetDistribution d(type, a.x, a.y);
            test::SphereChi2Options o;
            o.hemisphere = true;
            o.samples = 100000;
            o.seed = 77;
            o.significance = level;
            const test::Chi2Result r = test::chi2_sphere(
                [&](Rng& rng) {
                    return std::optional<Vec3>(d.sample_D({rng.next_float(), rng.next_float()}));
                },
                [&](Vec3 h) { return double(d.pdf_D(h)); }, o);
            EXPECT_TRUE(r.passed) << describe(type, a) << "\n" << r.report;
        }
}

TEST(AnisotropicMicrofacet, MaskingIsBoundedAndSymmetric) {
    Rng rng(5);
    for (MicrofacetType type : kTypes)
        for (Vec2 a : kAlphas) {
            const MicrofacetDistribution d(type, a.x, a.y);
            EXPECT_FLOAT_EQ(d.G1(Vec3(0, 0, 1)), 1.0f);
            for (int i = 0; i < 100; ++i) {
                const Vec3 wo = test::random_direction(rng), wi = test::random_direction(rng);
                const float g = d.G(wo, wi);
                EXPECT_LE(g, std::min(d.G1(wo), d.G1(wi)) * (1 + 1e-6f));
                EXPECT_GE(g, d.G1(wo) * d.G1(wi) * (1 - 1e-6f));
                EXPECT_FLOAT_EQ(g, d.G(wi, wo));
                // The roughness seen along x is alpha_x's: a mirror image in y changes nothing.
                EXPECT_FLOAT_EQ(d.lambda(wo), d.lambda(Vec3(wo.x, -wo.y, wo.z)));
            }
            // Along an axis, Lambda is the isotropic one of that axis' alpha.
            const MicrofacetDistribution ax(type, a.x), ay(type, a.y);
            const Vec3 along_x = spherical_direction(0.2f, 0), along_y = spherical_direction(0.2f, 1.5707964f);
            EXPECT_NEAR(d.lambda(along_x), ax.lambda(along_x), 1e-5f * ax.lambda(along_x));
            EXPECT_NEAR(d.lambda(along_y), ay.lambda(along_y), 1e-4f * ay.lambda(along_y) + 1e-6f);
        }
}

}  // namespace
}  // namespace penumbra
