// Dielectric interfaces. Smooth: exact Fresnel split, Snell directions, total internal
// reflection, the 1/eta^2 radiance factor, R + T = 1. Rough (Walter et al. 2007):
// sampling against the pdf over the whole sphere from both sides, GGX and Beckmann,
// alpha 1e-3 to 1, both transport modes; eval/pdf agreement; reflection reciprocity and
// the adjoint relation of the two modes for refraction; the white furnace.
#include "materials/lobes/dielectric.h"

#include <gtest/gtest.h>

#include <sstream>

#include "materials/lobes/fresnel.h"
#include "support/bsdf/bsdf_properties.h"

namespace penumbra {
namespace {

using test::spherical_direction;

DielectricParams params(float eta, float alpha, MicrofacetType type = MicrofacetType::Ggx) {
    DielectricParams p;
    p.eta = eta;
    p.alpha = alpha;
    p.distribution = type;
    return p;
}

std::string describe(const DielectricParams& p, Vec3 wo, Transport mode) {
    std::ostringstream s;
    s << (p.distribution == MicrofacetType::Ggx ? "GGX" : "Beckmann") << ", eta " << p.eta
      << ", alpha " << p.alpha << ", masking " << int(p.masking) << ", wo.z " << wo.z
      << (mode == Transport::Radiance ? ", radiance" : ", importance");
    return s.str();
}

TEST(DielectricBsdf, SmoothSplitsByExactFresnel) {
    for (float eta : {1.33f, 1.5f})
        for (float cos_o : {1.0f, 0.7f, 0.2f, -0.9f, -0.5f}) {
            const DielectricBsdf bsdf(params(eta, 0));
            ASSERT_TRUE(bsdf.has_specular());
            const Vec3 wo = spherical_direction(cos_o, 0.6f);
            const float F = fresnel_dielectric(cos_o, eta);
            const float etap = cos_o > 0 ? eta : 1 / eta;
            for (Transport mode : {Transport::Radiance, Transport::Importance}) {
                // u_lobe below F reflects, above refracts.
                const auto r = bsdf.sample(wo, 0.999f * F, {0.5f, 0.5f}, mode);
                ASSERT_TRUE(r);
                EXPECT_TRUE(r->is_specular());
                EXPECT_FLOAT_EQ(r->pdf, F);
                EXPECT_EQ(r->wi, Vec3(-wo.x, -wo.y, wo.z));
                EXPECT_NEAR(r->weight().x, 1.0f, 1e-5f);
                EXPECT_EQ(r->eta, 1.0f);
                if (F >= 1) continue;
                const auto t = bsdf.sample(wo, F + 0.999f * (1 - F), {0.5f, 0.5f}, mode);
                ASSERT_TRUE(t);
                EXPECT_TRUE(t->is_specular());
                EXPECT_FLOAT_EQ(t->pdf, 1 - F);
                EXPECT_EQ(t->eta, etap);
                EXPECT_LT(t->wi.z * wo.z, 0.0f);
                // Snell: sin_o = etap sin_t, in the plane of incidence, opposite side.
                EXPECT_NEAR(wo.x, -etap * t->wi.x, 1e-5f);
                EXPECT_NEAR(wo.y, -etap * t->wi.y, 1e-5f);
                const float expected = mode == Transport::Radiance ? 1 / (etap * etap) : 1.0f;
                EXPECT_NEAR(t->weight().x, expected, 1e-5f * expected);
            }
        }
}

TEST(DielectricBsdf, SmoothReflectsEverythingBeyondTheCriticalAngle) {
    const DielectricBsdf bsdf(params(1.5f, 0));
    const float cos_c = std::sqrt(1 - 1 / (1.5f * 1.5f));
    for (float cos_o : {-0.99f * cos_c, -0.3f, -0.02f})
        for (float u_lobe : {0.0f, 0.5f, 0.9999f}) {
            const Vec3 wo = spherical_direction(cos_o, 1.0f);
            const auto s = bsdf.sample(wo, u_lobe, {0.5f, 0.5f}, Transport::Radiance);
            ASSERT_TRUE(s);
            EXPECT_EQ(s->pdf, 1.0f);
            EXPECT_EQ(s->wi, Vec3(-wo.x, -wo.y, wo.z));
            EXPECT_NEAR(s->weight().x, 1.0f, 1e-6f);
        }
}

TEST(DielectricBsdf, SmoothWhiteFurnace) {
    // Importance: every sample weighs exactly 1 (R + T = 1). Radiance: R + T / etap^2.
    for (float cos_o : {1.0f, 0.5f, 0.05f, -0.3f, -0.95f}) {
        const Vec3 wo = spherical_direction(cos_o, 2.0f);
        const DielectricBsdf bsdf(params(1.5f, 0));
        const test::AlbedoEstimate imp =
            test::directional_albedo(bsdf, wo, 10000, 7, Transport::Importance);
        EXPECT_NEAR(imp.mean.x, 1.0f, 1e-5f) << "cos_o " << cos_o;
        const test::AlbedoEstimate rad =
            test::directional_albedo(bsdf, wo, 10000, 7, Transport::Radiance);
        const float F = fresnel_dielectric(cos_o, 1.5f), etap = cos_o > 0 ? 1.5f : 1 / 1.5f;
        EXPECT_NEAR(rad.mean.x, F + (1 - F) / (etap * etap), 4 * rad.std_error.x + 1e-5f)
            << "cos_o " << cos_o;
    }
}

TEST(DielectricBsdf, RoughSamplesFollowThePdf) {
    // The whole sphere: reflection and refraction, from outside and from inside.
    const MicrofacetType types[] = {MicrofacetType::Ggx, MicrofacetType::Beckmann};
    // From inside, cos -0.9 refracts and -0.6 lies beyond the critical angle (TIR but
    // for rough facets).
    const float alphas[] = {1e-3f, 0.2f, 1.0f};
    const float cos_os[] = {0.9f, 0.05f, -0.9f, -0.6f};
    const int tests = 2 * std::size(alphas) * std::size(cos_os);
    test::BsdfChi2Options o;
    o.samples = 100000;
    o.significance = test::sidak_significance(0.01, tests);
    int seed = 500;
    for (MicrofacetType type : types)
        for (float alpha : alphas)
            for (float cos_o : cos_os) {
                DielectricParams p = params(1.5f, alpha, type);
                // The pdf is the same for both masking models and modes: alternate them.
                p.masking = seed % 2 ? MaskingModel::SmithSeparable : MaskingModel::SmithCorrelated;
                const Transport mode = seed % 3 ? Transport::Radiance : Transport::Importance;
                const DielectricBsdf bsdf(p);
                const Vec3 wo = spherical_direction(cos_o, 0.4f);
                o.seed = ++seed;
                const test::Chi2Result r =
                    alpha < 0.01f ? test::bsdf_chi2_half_vector(bsdf, wo, alpha, p.eta, o, mode)
                                  : test::bsdf_chi2_sphere(bsdf, wo, o, mode);
                EXPECT_TRUE(r.passed) << describe(p, wo, mode) << "\n" << r.report;
                const double lost = double(r.lost) / r.samples;
                EXPECT_NEAR(r.pdf_integral, 1 - lost, 5 * std::sqrt(lost / r.samples) + 2e-4)
                    << describe(p, wo, mode);
            }
}

TEST(DielectricBsdf, RoughSampleAgreesWithEvalAndPdf) {
    Rng rng(9);
    for (int i = 0; i < 200; ++i) {
        DielectricParams p =
            params(i % 3 ? 1.5f : 1.33f, i % 10 == 0 ? 1e-3f : 0.02f + rng.next_float(),
                   i % 2 ? MicrofacetType::Beckmann : MicrofacetType::Ggx);
        p.transmittance = {0.9f, 0.5f, 0.2f};
        const Transport mode = i % 4 < 2 ? Transport::Radiance : Transport::Importance;
        const Vec3 wo = test::random_direction(rng, 0.02f, i % 5 == 0);
        const DielectricBsdf bsdf(p);
        EXPECT_EQ(test::check_sample_agreement(bsdf, wo, 50, i, mode), "") << describe(p, wo, mode);
        // Refracted samples report the relative IOR the path crossed.
        const auto s = bsdf.sample(wo, 0.999f, {0.3f, 0.4f}, mode);
        if (s && s->wi.z * wo.z < 0) {
            EXPECT_EQ(s->eta, wo.z > 0 ? p.eta : 1 / p.eta);
        }
    }
}

TEST(DielectricBsdf, RoughReciprocityAndAdjoint) {
    Rng rng(10);
    for (int i = 0; i < 8; ++i) {
        const DielectricParams p =
            params(1.5f, 0.05f + 0.25f * i, i % 2 ? MicrofacetType::Beckmann : MicrofacetType::Ggx);
        const DielectricBsdf bsdf(p);
        // Reflection on either side is reciprocal.
        EXPECT_EQ(test::check_reciprocity(bsdf, 200, i), "");
        for (int k = 0; k < 200; ++k) {
            const Vec3 a = test::random_direction(rng, 0.02f),
                       b = test::random_direction(rng, 0.02f);
            const Vec3 lower(b.x, b.y, -b.z), lower_a(a.x, a.y, -a.z);
            const Spectrum fl = bsdf.eval(lower_a, lower, Transport::Radiance);
            EXPECT_NEAR(fl.x, bsdf.eval(lower, lower_a, Transport::Radiance).x, 1e-4f * fl.x);
            // Refraction: the importance BSDF is the radiance one with arguments swapped
            // (Veach 1997, eq. 5.20), so the eta^2 factor sits on the right side.
            const Spectrum imp = bsdf.eval(a, lower, Transport::Importance);
            const Spectrum rad = bsdf.eval(lower, a, Transport::Radiance);
            if (rad.x < 1e-30f) continue;  // denormals carry no relative precision
            EXPECT_NEAR(imp.x, rad.x, 2e-4f * std::max(imp.x, rad.x))
                << describe(p, a, Transport::Radiance);
            // And radiance crossing into the denser side gains eta^2 (Veach eq. 5.11).
            const Spectrum rad_in = bsdf.eval(a, lower, Transport::Radiance);
            EXPECT_NEAR(rad_in.x * p.eta * p.eta, rad.x, 2e-4f * rad.x);
        }
    }
}

TEST(DielectricBsdf, RoughWhiteFurnace) {
    // Energy conservation is the importance albedo (light arriving from wo): <= 1 from
    // both sides. In radiance, from outside, the 1/eta^2 only lowers it further.
    for (MicrofacetType type : {MicrofacetType::Ggx, MicrofacetType::Beckmann})
        for (float alpha : {1e-3f, 0.2f, 0.6f, 1.0f})
            for (float cos_o : {1.0f, 0.3f, 0.05f, -0.8f, -0.1f}) {
                const DielectricParams p = params(1.5f, alpha, type);
                const Vec3 wo = spherical_direction(cos_o, 0.5f);
                const DielectricBsdf bsdf(p);
                for (Transport mode : {Transport::Importance, Transport::Radiance}) {
                    if (mode == Transport::Radiance && cos_o < 0) continue;
                    const test::AlbedoEstimate a =
                        test::directional_albedo(bsdf, wo, 20000, 12, mode);
                    EXPECT_LE(a.mean.x, 1 + 3 * a.std_error.x + 1e-5f)
                        << describe(p, wo, mode) << ": albedo " << a.mean.x << " +- "
                        << a.std_error.x;
                }
                // Nearly smooth and head-on, next to nothing is lost to masking.
                if (alpha == 1e-3f && std::abs(cos_o) > 0.5f) {
                    EXPECT_NEAR(
                        test::directional_albedo(bsdf, wo, 20000, 12, Transport::Importance).mean.x,
                        1.0f, 1e-3f);
                }
            }
}

TEST(DielectricBsdf, IndexMatchedPassesStraightThrough) {
    const DielectricBsdf bsdf(params(1.0f, 0.4f));
    EXPECT_TRUE(bsdf.has_specular());
    const Vec3 wo = spherical_direction(0.3f, 1.0f);
    const auto s = bsdf.sample(wo, 0.5f, {0.2f, 0.7f}, Transport::Radiance);
    ASSERT_TRUE(s);
    EXPECT_NEAR(s->wi.x, -wo.x, 1e-6f);
    EXPECT_NEAR(s->wi.z, -wo.z, 1e-6f);
    EXPECT_NEAR(s->weight().x, 1.0f, 1e-6f);
}

}  // namespace
}  // namespace penumbra
