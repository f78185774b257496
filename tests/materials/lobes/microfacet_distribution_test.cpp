// Beckmann and the run-time MicrofacetDistribution of materials/lobes/microfacet.h (GGX alone
// is covered by microfacet_test.cpp): normalization of D and of the visible normals,
// their sampling against their pdfs, D sampling, and the three masking models.
#include <gtest/gtest.h>

#include <cmath>

#include "materials/lobes/microfacet.h"
#include "support/bsdf/bsdf_checks.h"
#include "support/statistics/chi2.h"
#include "support/statistics/quadrature.h"

namespace penumbra {
namespace {

using test::spherical_direction;

const float kAlphas[] = {1e-3f, 0.05f, 0.3f, 0.7f, 1.0f};
const MicrofacetType kTypes[] = {MicrofacetType::Ggx, MicrofacetType::Beckmann};
const char* name(MicrofacetType t) { return t == MicrofacetType::Ggx ? "GGX" : "Beckmann"; }

// Integral over the hemisphere of f(h) dh, in (theta, phi) so narrow peaks are resolved.
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

TEST(ErfInv, InvertsErf) {
    for (double y = -0.999999; y < 1; y += 0.0137)
        EXPECT_NEAR(std::erf(erf_inv(y)), y, 1e-12 * std::max(1.0, 1 / (1 - std::abs(y))));
    EXPECT_EQ(erf_inv(0), 0);
    EXPECT_TRUE(std::isinf(erf_inv(1)) && std::isinf(erf_inv(-1)));
}

TEST(BeckmannDistribution, ProjectedAreaIsNormalized) {
    for (float alpha : kAlphas) {
        const BeckmannDistribution d(alpha);
        const double integral = test::integrate_1d(
            [&](double theta) {
                const Vec3 h(float(std::sin(theta)), 0, float(std::cos(theta)));
                return 2 * M_PI * d.D(h) * std::cos(theta) * std::sin(theta);
            },
            0, M_PI / 2, 1e-8, 1e-8, 8, 2000);
        EXPECT_NEAR(integral, 1.0, 1e-4) << "alpha " << alpha;
    }
}

TEST(MicrofacetDistribution, VisibleNormalsAreNormalized) {
    // The integral of G1(wo) max(0, wo.h) D(h) / wo.z is 1 only with the exact Lambda:
    // this checks Beckmann's erfc form against its D.
    for (MicrofacetType type : kTypes)
        for (float alpha : kAlphas)
            for (float cos_o : {1.0f, 0.7f, 0.3f, 0.05f}) {
                const MicrofacetDistribution d(type, alpha);
                const Vec3 wo = spherical_direction(cos_o, 0.4f);
                const double integral =
                    integrate_hemisphere([&](Vec3 h) { return d.pdf_visible(wo, h); });
                EXPECT_NEAR(integral, 1.0, 2e-4)
                    << name(type) << ", alpha " << alpha << ", cos_o " << cos_o;
            }
}

TEST(MicrofacetDistribution, DispatchesToTheConcreteDistribution) {
    Rng rng(3);
    for (int i = 0; i < 200; ++i) {
        const float alpha = 0.01f + rng.next_float();
        const Vec3 h = spherical_direction(rng.next_float(), 6 * rng.next_float());
        const Vec3 w = spherical_direction(0.05f + 0.95f * rng.next_float(), 6 * rng.next_float());
        const Vec2 u(rng.next_float(), rng.next_float());
        const GgxDistribution g(alpha);
        const BeckmannDistribution b(alpha);
        const MicrofacetDistribution mg(MicrofacetType::Ggx, alpha);
        const MicrofacetDistribution mb(MicrofacetType::Beckmann, alpha);
        EXPECT_EQ(mg.D(h), g.D(h));
        EXPECT_EQ(mb.D(h), b.D(h));
        EXPECT_EQ(mg.G1(w), g.G1(w));
        EXPECT_EQ(mb.G1(w), b.G1(w));
        EXPECT_EQ(mg.sample_visible(w, u), g.sample_visible(w, u));
        EXPECT_EQ(mb.sample_visible(w, u), b.sample_visible(w, u));
    }
}

TEST(MicrofacetDistribution, SamplesFollowTheirPdfs) {
    // Visible normals (both types) and D itself; narrow lobes fall in one cell here,
    // so alphas from 0.1 (the BSDF tests bin narrow lobes by their half vectors).
    const float alphas[] = {0.1f, 1.0f};
    const float cos_os[] = {1.0f, 0.05f};
    const int tests = 2 * 2 * (2 + 1);
    const double level = test::sidak_significance(0.01, tests);
    int seed = 100;
    for (MicrofacetType type : kTypes)
        for (float alpha : alphas) {
            const MicrofacetDistribution d(type, alpha);
            test::SphereChi2Options o;
            o.hemisphere = true;
            o.samples = 100000;
            o.significance = level;
            for (float cos_o : cos_os) {
                const Vec3 wo = spherical_direction(cos_o, -1.1f);
                o.seed = ++seed;
                const test::Chi2Result r = test::chi2_sphere(
                    [&](Rng& rng) {
                        return std::optional<Vec3>(
                            d.sample_visible(wo, {rng.next_float(), rng.next_float()}));
                    },
                    [&](Vec3 h) { return double(d.pdf_visible(wo, h)); }, o);
                EXPECT_TRUE(r.passed)
                    << name(type) << " visible, alpha " << alpha << ", cos_o " << cos_o << "\n"
                    << r.report;
            }
            o.seed = ++seed;
            const test::Chi2Result r = test::chi2_sphere(
                [&](Rng& rng) {
                    return std::optional<Vec3>(d.sample_D({rng.next_float(), rng.next_float()}));
                },
                [&](Vec3 h) { return double(d.pdf_D(h)); }, o);
            EXPECT_TRUE(r.passed) << name(type) << " D, alpha " << alpha << "\n" << r.report;
        }
}

TEST(MicrofacetDistribution, MaskingModelsAreBoundedAndSymmetric) {
    Rng rng(4);
    for (MicrofacetType type : kTypes)
        for (float alpha : kAlphas) {
            const MicrofacetDistribution d(type, alpha);
            for (int i = 0; i < 200; ++i) {
                const Vec3 wo =
                    spherical_direction(0.02f + 0.98f * rng.next_float(), 6 * rng.next_float());
                const Vec3 wi =
                    spherical_direction(0.02f + 0.98f * rng.next_float(), 6 * rng.next_float());
                const Vec3 h = normalize(wo + wi);
                const float corr = d.G(wo, wi, h, MaskingModel::SmithCorrelated);
                const float sep = d.G(wo, wi, h, MaskingModel::SmithSeparable);
                const float vcav = d.G(wo, wi, h, MaskingModel::VCavity);
                EXPECT_EQ(corr, d.G(wo, wi));
                // Correlation only removes double-counted occlusion (Heitz 2014, sec. 6).
                EXPECT_GE(corr, sep * (1 - 1e-6f));
                EXPECT_LE(corr, std::min(d.G1(wo), d.G1(wi)) * (1 + 1e-6f));
                EXPECT_GE(vcav, 0.0f);
                EXPECT_LE(vcav, 1.0f);
                for (MaskingModel m : {MaskingModel::SmithCorrelated, MaskingModel::SmithSeparable,
                                       MaskingModel::VCavity})
                    EXPECT_NEAR(d.G(wo, wi, h, m), d.G(wi, wo, h, m), 1e-6f);
            }
            // Seen and lit from the normal nothing is masked.
            const Vec3 n(0, 0, 1);
            EXPECT_FLOAT_EQ(d.G(n, n, n, MaskingModel::VCavity), 1.0f);
            EXPECT_FLOAT_EQ(d.G(n, n, n, MaskingModel::SmithSeparable), 1.0f);
        }
    // The V-cavity term written out (Cook & Torrance 1982) for one configuration.
    const MicrofacetDistribution d(MicrofacetType::Beckmann, 0.3f);
    const Vec3 wo = spherical_direction(0.2f, 0), wi = spherical_direction(0.9f, 2.5f);
    const Vec3 h = normalize(wo + wi);
    const float expected =
        std::min({1.0f, 2 * h.z * wo.z / dot(wo, h), 2 * h.z * wi.z / dot(wo, h)});
    EXPECT_FLOAT_EQ(d.G(wo, wi, h, MaskingModel::VCavity), expected);
    EXPECT_LT(expected, 1.0f);
}

TEST(BeckmannDistribution, LambdaMatchesTheWalterApproximation) {
    // Walter et al. 2007, eq. 27's rational fit of the same G1, accurate to ~1e-3.
    const float alpha = 0.4f;
    const BeckmannDistribution d(alpha);
    for (float cos_t : {0.9f, 0.6f, 0.3f, 0.1f, 0.02f}) {
        const Vec3 w = spherical_direction(cos_t, 1.0f);
        const float a = cos_t / (alpha * std::sqrt(1 - cos_t * cos_t));
        const float approx =
            a >= 1.6f ? 1.0f : (3.535f * a + 2.181f * a * a) / (1 + 2.276f * a + 2.577f * a * a);
        EXPECT_NEAR(d.G1(w), approx, 3e-3f) << "cos " << cos_t;
    }
}

}  // namespace
}  // namespace penumbra
