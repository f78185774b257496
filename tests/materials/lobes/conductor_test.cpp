// Conductors: the mirror reflects F of the complex IOR, the rough lobe samples its pdf
// (GGX and Beckmann, alpha from 1e-3 to 1, grazing wo), agrees with eval, is reciprocal,
// and never reflects more than F = 1 would.
#include "materials/lobes/conductor.h"

#include <gtest/gtest.h>

#include "support/bsdf/bsdf_properties.h"

namespace penumbra {
namespace {

using test::spherical_direction;

const Metal kMetals[] = {Metal::Gold, Metal::Copper, Metal::Aluminium, Metal::Silver};

TEST(ConductorBsdf, MirrorReflectsTheConductorFresnel) {
    for (Metal m : kMetals) {
        const ConductorBsdf bsdf(m, MicrofacetType::Ggx, 0);
        ASSERT_TRUE(bsdf.has_specular());
        const ComplexIor ior = metal_ior(m);
        for (float cos_o : {1.0f, 0.5f, 0.05f}) {
            const Vec3 wo = spherical_direction(cos_o, 2.2f);
            const auto s = bsdf.sample(wo, 0.7f, {0.1f, 0.9f}, Transport::Radiance);
            ASSERT_TRUE(s);
            EXPECT_TRUE(s->is_specular());
            const Spectrum F = fresnel_conductor(cos_o, ior.eta, ior.k);
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(s->weight()[c], F[c], 1e-5f);
        }
    }
}

TEST(ConductorBsdf, SamplesFollowThePdf) {
    const MicrofacetType types[] = {MicrofacetType::Ggx, MicrofacetType::Beckmann};
    // The pdf is Cook-Torrance's (cook_torrance_test.cpp sweeps it): a lighter sweep.
    const float alphas[] = {1e-3f, 0.5f};
    const float cos_os[] = {0.8f, 0.05f};
    test::BsdfChi2Options o;
    o.samples = 100000;
    o.significance = test::sidak_significance(0.01, 2 * 2 * 2);
    int seed = 400;
    for (MicrofacetType type : types)
        for (float alpha : alphas)
            for (float cos_o : cos_os) {
                const ConductorBsdf bsdf(Metal::Gold, type, alpha);
                const Vec3 wo = spherical_direction(cos_o, -2.0f);
                o.seed = ++seed;
                const test::Chi2Result r = alpha < 0.01f
                                               ? test::bsdf_chi2_half_vector(bsdf, wo, alpha, 0, o)
                                               : test::bsdf_chi2(bsdf, wo, o);
                EXPECT_TRUE(r.passed)
                    << "type " << int(type) << ", alpha " << alpha << ", cos_o " << cos_o << "\n"
                    << r.report;
            }
}

TEST(ConductorBsdf, SampleAgreesWithEvalAndPdfAndIsReciprocal) {
    Rng rng(6);
    for (int i = 0; i < 16; ++i) {
        const MicrofacetType type = i % 2 ? MicrofacetType::Beckmann : MicrofacetType::Ggx;
        const float alpha = i < 2 ? 1e-3f : 0.05f + 0.95f * rng.next_float();
        const ConductorBsdf bsdf(kMetals[i % 4], type, alpha);
        for (int k = 0; k < 10; ++k) {
            const Vec3 wo = test::random_direction(rng);
            EXPECT_EQ(test::check_sample_agreement(bsdf, wo, 50, k, Transport::Importance), "");
        }
        EXPECT_EQ(test::check_reciprocity(bsdf, 200, i), "") << "alpha " << alpha;
    }
}

TEST(ConductorBsdf, WhiteFurnace) {
    // Real metals absorb: below 1 everywhere, and below the F = 1 (white) albedo.
    for (Metal m : {Metal::Gold, Metal::Silver})
        for (float alpha : {0.0f, 0.1f, 0.5f, 1.0f})
            for (float cos_o : {1.0f, 0.4f, 0.05f}) {
                const Vec3 wo = spherical_direction(cos_o, 0.1f);
                const test::AlbedoEstimate a = test::directional_albedo(
                    ConductorBsdf(m, MicrofacetType::Beckmann, alpha), wo, 20000, 8);
                for (int c = 0; c < 3; ++c)
                    EXPECT_LE(a.mean[c], 1 + 3 * a.std_error[c] + 1e-5f)
                        << "alpha " << alpha << ", cos_o " << cos_o;
            }
}

}  // namespace
}  // namespace penumbra
