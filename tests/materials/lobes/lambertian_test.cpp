#include "materials/lobes/lambertian.h"

#include <gtest/gtest.h>

#include "support/bsdf/bsdf_checks.h"

namespace penumbra {
namespace {

using test::spherical_direction;

const float kCosOs[] = {1.0f, 0.6f, 0.05f};

TEST(LambertianBsdf, SamplesFollowThePdf) {
    const LambertianBsdf bsdf(Spectrum(0.2f, 0.5f, 0.8f));
    test::BsdfChi2Options o;
    o.significance = test::sidak_significance(0.01, 3);
    for (float cos_o : kCosOs) {
        o.seed = 31;
        const test::Chi2Result r = test::bsdf_chi2(bsdf, spherical_direction(cos_o, 0.7f), o);
        EXPECT_TRUE(r.passed) << "cos_o " << cos_o << "\n" << r.report;
        EXPECT_NEAR(r.pdf_integral, 1.0, 1e-5);
        // Only a direction rounded onto the horizon (pdf 0) is returned as no sample.
        EXPECT_LE(r.lost, 5u);
    }
}

TEST(LambertianBsdf, SampleAgreesWithEvalAndPdf) {
    const LambertianBsdf bsdf(Spectrum(0.2f, 0.5f, 0.8f));
    Rng rng(5);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 wo = spherical_direction(0.01f + 0.99f * rng.next_float(), 6 * rng.next_float());
        const auto s = bsdf.sample(wo, rng.next_float(), {rng.next_float(), rng.next_float()},
                                   Transport::Radiance);
        ASSERT_TRUE(s);
        EXPECT_EQ(s->lobe, Lobe::Diffuse);
        EXPECT_EQ(s->f, bsdf.eval(wo, s->wi, Transport::Radiance));
        EXPECT_EQ(s->pdf, bsdf.pdf(wo, s->wi, Transport::Radiance));
        EXPECT_EQ(bsdf.eval(wo, s->wi, Transport::Radiance),
                  bsdf.eval(s->wi, wo, Transport::Radiance));
    }
}

TEST(LambertianBsdf, WhiteFurnace) {
    // f cos / pdf is R exactly: a white Lambertian reflects everything, a grey one R.
    for (float cos_o : kCosOs) {
        const Vec3 wo = spherical_direction(cos_o, 0.2f);
        const test::AlbedoEstimate white =
            test::directional_albedo(LambertianBsdf(Spectrum(1)), wo, 20000, 3);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(white.mean[c], 1.0f, 1e-5f);
        const test::AlbedoEstimate grey =
            test::directional_albedo(LambertianBsdf(Spectrum(0.25f, 0.5f, 0.75f)), wo, 20000, 3);
        EXPECT_NEAR(grey.mean.x, 0.25f, 1e-5f);
        EXPECT_NEAR(grey.mean.z, 0.75f, 1e-5f);
    }
}

TEST(LambertianBsdf, NothingBelowTheHorizon) {
    const LambertianBsdf bsdf(Spectrum(1));
    const Vec3 up = spherical_direction(0.5f, 1), down = spherical_direction(-0.5f, 1);
    EXPECT_TRUE(is_black(bsdf.eval(up, down, Transport::Radiance)));
    EXPECT_TRUE(is_black(bsdf.eval(down, up, Transport::Radiance)));
    EXPECT_EQ(bsdf.pdf(up, down, Transport::Radiance), 0.0f);
    EXPECT_EQ(bsdf.pdf(down, up, Transport::Radiance), 0.0f);
    EXPECT_FALSE(bsdf.sample(down, 0.5f, {0.3f, 0.6f}, Transport::Radiance));
    EXPECT_FALSE(bsdf.has_specular());
}

}  // namespace
}  // namespace penumbra
