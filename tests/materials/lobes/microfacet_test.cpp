#include "materials/lobes/microfacet.h"

#include <gtest/gtest.h>

#include <cmath>

#include "support/bsdf/bsdf_checks.h"
#include "support/statistics/chi2.h"
#include "support/statistics/quadrature.h"

namespace penumbra {
namespace {

using test::spherical_direction;

const float kAlphas[] = {1e-3f, 0.0025f, 0.09f, 0.3f, 0.49f, 1.0f};

// (1e-3 is roughness 0.03: a polished surface whose lobe is a few ulps of cos(theta)
// wide, which is where float precision runs out first.)
TEST(GgxDistribution, ProjectedAreaIsNormalized) {
    for (float alpha : kAlphas) {
        const GgxDistribution ggx(alpha);
        // Integral of D(h) cos(theta_h) over the hemisphere, in theta: the peak is
        // resolved in theta where it is not in cos(theta).
        const double integral = test::integrate_1d(
            [&](double theta) {
                const Vec3 h(float(std::sin(theta)), 0, float(std::cos(theta)));
                return 2 * M_PI * ggx.D(h) * std::cos(theta) * std::sin(theta);
            },
            0, M_PI / 2, 1e-8, 1e-8, 8, 2000);
        EXPECT_NEAR(integral, 1.0, 1e-4) << "alpha " << alpha;
    }
}

TEST(GgxDistribution, VisibleNormalPdfIsNormalized) {
    for (float alpha : kAlphas)
        for (float cos_o : {1.0f, 0.7f, 0.3f, 0.05f}) {
            const GgxDistribution ggx(alpha);
            const Vec3 wo = spherical_direction(cos_o, 0.4f);
            const double integral = test::integrate_2d(
                [&](double theta, double phi) {
                    const Vec3 h(float(std::sin(theta) * std::cos(phi)),
                                 float(std::sin(theta) * std::sin(phi)), float(std::cos(theta)));
                    return ggx.pdf_visible(wo, h) * std::sin(theta);
                },
                0, M_PI / 2, 0, 2 * M_PI, 1e-7);
            EXPECT_NEAR(integral, 1.0, 1e-4) << "alpha " << alpha << ", cos_o " << cos_o;
        }
}

TEST(GgxDistribution, VisibleNormalSamplesFollowTheirPdf) {
    // Narrow lobes sit in one or two cells: only the wider ones say much here (the
    // BSDF tests bin the reflected directions, where narrow lobes are far from z).
    const float alphas[] = {0.09f, 0.3f, 0.49f, 1.0f};
    const float cos_os[] = {1.0f, 0.5f, 0.05f};
    const double level = test::sidak_significance(0.01, 4 * 3);
    for (float alpha : alphas)
        for (float cos_o : cos_os) {
            const GgxDistribution ggx(alpha);
            const Vec3 wo = spherical_direction(cos_o, -1.1f);
            test::SphereChi2Options o;
            o.hemisphere = true;
            o.seed = 21;
            o.significance = level;
            const test::Chi2Result r = test::chi2_sphere(
                [&](Rng& rng) {
                    return std::optional<Vec3>(
                        ggx.sample_visible(wo, {rng.next_float(), rng.next_float()}));
                },
                [&](Vec3 h) { return double(ggx.pdf_visible(wo, h)); }, o);
            EXPECT_TRUE(r.passed) << "alpha " << alpha << ", cos_o " << cos_o << "\n" << r.report;
        }
}

TEST(GgxDistribution, VanishesBelowTheHorizon) {
    const GgxDistribution ggx(0.3f);
    const Vec3 below = normalize(Vec3(0.3f, 0.1f, -0.5f)), wo = spherical_direction(0.6f, 0);
    EXPECT_EQ(ggx.D(below), 0.0f);
    EXPECT_EQ(ggx.D(Vec3(1, 0, 0)), 0.0f);
    EXPECT_EQ(ggx.pdf_visible(wo, below), 0.0f);
    // A microfacet facing away from wo is invisible.
    EXPECT_EQ(ggx.pdf_visible(wo, normalize(Vec3(-wo.x, -wo.y, 0.01f))), 0.0f);
    EXPECT_EQ(ggx.pdf_visible(-wo, Vec3(0, 0, 1)), 0.0f);
}

TEST(GgxDistribution, MaskingIsBoundedAndSymmetric) {
    for (float alpha : kAlphas) {
        const GgxDistribution ggx(alpha);
        EXPECT_FLOAT_EQ(ggx.G1(Vec3(0, 0, 1)), 1.0f);
        for (float ci : {0.9f, 0.4f, 0.05f})
            for (float co : {0.8f, 0.2f}) {
                const Vec3 wi = spherical_direction(ci, 0.3f), wo = spherical_direction(co, 2);
                const float g = ggx.G(wo, wi);
                EXPECT_LE(g, std::min(ggx.G1(wo), ggx.G1(wi)) * (1 + 1e-6f));
                EXPECT_GE(g, ggx.G1(wo) * ggx.G1(wi) * (1 - 1e-6f));
                EXPECT_FLOAT_EQ(g, ggx.G(wi, wo));
            }
    }
}

}  // namespace
}  // namespace penumbra
