// The classic microfacet reflection model with every D, G and F: sampling against pdf
// (visible normals for Smith, D for the V-cavity), agreement with eval/pdf, reciprocity
// and the white furnace; below kDeltaAlpha a mirror scaled by F.
#include "materials/lobes/cook_torrance.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "support/bsdf/bsdf_properties.h"

namespace penumbra {
namespace {

using test::spherical_direction;

const MicrofacetType kTypes[] = {MicrofacetType::Ggx, MicrofacetType::Beckmann};
const MaskingModel kMasking[] = {MaskingModel::SmithCorrelated, MaskingModel::SmithSeparable,
                                 MaskingModel::VCavity};
const float kAlphas[] = {1e-3f, 0.2f, 1.0f};
const float kCosOs[] = {0.95f, 0.05f};

std::string describe(const CookTorranceParams& p, Vec3 wo) {
    std::ostringstream s;
    s << (p.distribution == MicrofacetType::Ggx ? "GGX" : "Beckmann") << ", masking "
      << int(p.masking) << ", fresnel " << int(p.fresnel.model) << ", alpha " << p.alpha
      << ", wo.z " << wo.z;
    return s.str();
}

Fresnel fresnel(int i) {
    switch (i % 3) {
        case 0:
            return Fresnel::schlick(Spectrum(0.9f, 0.6f, 0.3f));
        case 1:
            return Fresnel::dielectric(1.5f);
        default:
            return Fresnel::conductor(metal_ior(Metal::Copper));
    }
}

TEST(CookTorranceBsdf, SamplesFollowThePdf) {
    // The pdf depends on the sampling only: visible normals (both Smith models) or D
    // (V-cavity); separable and correlated Smith share one sampler, so one is enough.
    const MaskingModel samplers[] = {MaskingModel::SmithCorrelated, MaskingModel::VCavity};
    const int tests = 2 * 2 * std::size(kAlphas) * std::size(kCosOs);
    test::BsdfChi2Options o;
    o.samples = 100000;
    o.significance = test::sidak_significance(0.01, tests);
    int seed = 200;
    for (MicrofacetType type : kTypes)
        for (MaskingModel masking : samplers)
            for (float alpha : kAlphas)
                for (float cos_o : kCosOs) {
                    CookTorranceParams p;
                    p.distribution = type;
                    p.masking = masking;
                    p.alpha = alpha;
                    const CookTorranceBsdf bsdf(p);
                    const Vec3 wo = spherical_direction(cos_o, 0.9f);
                    o.seed = ++seed;
                    // Lobes a few cells wide are binned by their microfacet normal.
                    const test::Chi2Result r =
                        alpha < 0.01f ? test::bsdf_chi2_half_vector(bsdf, wo, alpha, 0, o)
                                      : test::bsdf_chi2(bsdf, wo, o);
                    EXPECT_TRUE(r.passed) << describe(p, wo) << "\n" << r.report;
                    // What is not in the pdf is exactly what was lost below the horizon.
                    const double lost = double(r.lost) / r.samples;
                    EXPECT_NEAR(r.pdf_integral, 1 - lost, 5 * std::sqrt(lost / r.samples) + 1e-4)
                        << describe(p, wo);
                }
}

TEST(CookTorranceBsdf, SampleAgreesWithEvalAndPdf) {
    Rng rng(11);
    for (int i = 0; i < 300; ++i) {
        CookTorranceParams p;
        p.distribution = kTypes[i % 2];
        p.masking = kMasking[(i / 2) % 3];
        p.fresnel = fresnel(i / 6);
        p.alpha = i % 10 == 0 ? 1e-3f : 0.01f + rng.next_float();
        const Vec3 wo = test::random_direction(rng);
        const std::string e =
            test::check_sample_agreement(CookTorranceBsdf(p), wo, 50, i, Transport::Radiance);
        EXPECT_EQ(e, "") << describe(p, wo);
    }
}

TEST(CookTorranceBsdf, Reciprocity) {
    for (int i = 0; i < 18; ++i) {
        CookTorranceParams p;
        p.distribution = kTypes[i % 2];
        p.masking = kMasking[(i / 2) % 3];
        p.fresnel = fresnel(i / 6);
        p.alpha = 0.05f + 0.3f * (i % 4);
        EXPECT_EQ(test::check_reciprocity(CookTorranceBsdf(p), 200, i), "")
            << describe(p, Vec3(0, 0, 1));
    }
}

TEST(CookTorranceBsdf, WhiteFurnace) {
    // F = 1: the directional albedo is what masking leaves, never more than 1.
    for (MicrofacetType type : kTypes)
        for (MaskingModel masking : kMasking)
            for (float alpha : {1e-3f, 0.1f, 0.4f, 1.0f})
                for (float cos_o : {1.0f, 0.6f, 0.2f, 0.05f}) {
                    CookTorranceParams p;
                    p.distribution = type;
                    p.masking = masking;
                    p.alpha = alpha;
                    const Vec3 wo = spherical_direction(cos_o, 0.3f);
                    const test::AlbedoEstimate a =
                        test::directional_albedo(CookTorranceBsdf(p), wo, 20000, 13);
                    EXPECT_LE(a.mean.x, 1 + 3 * a.std_error.x + 1e-5f)
                        << describe(p, wo) << ": albedo " << a.mean.x << " +- " << a.std_error.x;
                    // Nearly smooth and seen from above almost nothing is masked.
                    if (alpha == 1e-3f && cos_o > 0.5f) {
                        EXPECT_NEAR(a.mean.x, 1.0f, 1e-3f);
                    }
                }
}

TEST(CookTorranceBsdf, MirrorBelowDeltaAlpha) {
    // F = 1 (i = 3, the default Fresnel) is the white mirror: every weight exactly 1.
    for (int i = 0; i < 4; ++i) {
        CookTorranceParams p;
        p.alpha = 0;
        if (i < 3) p.fresnel = fresnel(i);
        const CookTorranceBsdf bsdf(p);
        ASSERT_TRUE(bsdf.has_specular());
        for (float cos_o : kCosOs) {
            const Vec3 wo = spherical_direction(cos_o, 1.7f);
            const auto s = bsdf.sample(wo, 0.5f, {0.3f, 0.8f}, Transport::Radiance);
            ASSERT_TRUE(s);
            EXPECT_TRUE(s->is_specular());
            EXPECT_EQ(s->pdf, 1.0f);
            EXPECT_NEAR(s->wi.x, -wo.x, 1e-7f);
            EXPECT_NEAR(s->wi.z, wo.z, 1e-7f);
            const Spectrum F = p.fresnel.eval(cos_o);
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(s->weight()[c], F[c], 1e-5f * F[c]);
            if (i == 3) {
                EXPECT_EQ(s->weight(), Spectrum(1));
            }
            EXPECT_TRUE(is_black(bsdf.eval(wo, s->wi, Transport::Radiance)));
            EXPECT_EQ(bsdf.pdf(wo, s->wi, Transport::Radiance), 0.0f);
        }
    }
}

TEST(CookTorranceBsdf, MatchesTheClassicFormula) {
    // f = F D G / (4 cos_o cos_i), spelled out for Beckmann with the V-cavity term.
    CookTorranceParams p;
    p.distribution = MicrofacetType::Beckmann;
    p.masking = MaskingModel::VCavity;
    p.alpha = 0.35f;
    p.fresnel = Fresnel::dielectric(1.5f);
    const Vec3 wo = spherical_direction(0.3f, 0.2f), wi = spherical_direction(0.8f, 2.6f);
    const Vec3 h = normalize(wo + wi);
    const float tan2 = (1 - h.z * h.z) / (h.z * h.z), m2 = p.alpha * p.alpha;
    const float D = std::exp(-tan2 / m2) / (kPi * m2 * h.z * h.z * h.z * h.z);
    const float G = std::min({1.0f, 2 * h.z * wo.z / dot(wo, h), 2 * h.z * wi.z / dot(wo, h)});
    const float F = fresnel_dielectric(dot(wo, h), 1.5f);
    EXPECT_NEAR(CookTorranceBsdf(p).eval(wo, wi, Transport::Radiance).x,
                F * D * G / (4 * wo.z * wi.z), 1e-5f * F * D * G / (4 * wo.z * wi.z));
}

TEST(CookTorranceBsdf, NothingBelowTheHorizon) {
    CookTorranceParams p;
    p.alpha = 0.3f;
    const CookTorranceBsdf bsdf(p);
    const Vec3 up = spherical_direction(0.5f, 1), down = spherical_direction(-0.5f, 2);
    EXPECT_TRUE(is_black(bsdf.eval(up, down, Transport::Radiance)));
    EXPECT_TRUE(is_black(bsdf.eval(down, up, Transport::Radiance)));
    EXPECT_EQ(bsdf.pdf(up, down, Transport::Radiance), 0.0f);
    EXPECT_FALSE(bsdf.sample(down, 0.5f, {0.3f, 0.6f}, Transport::Radiance));
}

}  // namespace
}  // namespace penumbra
