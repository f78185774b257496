#include "support/statistics/chi2.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/sampling/warp.h"

namespace penumbra::test {
namespace {

Vec2 next_2d(Rng& rng) { return {rng.next_float(), rng.next_float()}; }

TEST(Chi2, PValuesMatchTables) {
    // Critical values from any chi-square table.
    EXPECT_NEAR(chi2_p_value(3.841459, 1), 0.05, 1e-6);
    EXPECT_NEAR(chi2_p_value(18.307038, 10), 0.05, 1e-6);
    EXPECT_NEAR(chi2_p_value(135.806723, 100), 0.01, 1e-6);
    EXPECT_NEAR(chi2_p_value(1.0, 2), std::exp(-0.5), 1e-12);  // Q(1, x) = e^-x
    EXPECT_NEAR(chi2_p_value(0.0, 5), 1.0, 1e-12);
    EXPECT_NEAR(gamma_q(0.5, 2.0), std::erfc(std::sqrt(2.0)), 1e-12);
    EXPECT_NEAR(gamma_q(3.0, 30.0), std::exp(-30.0) * (1 + 30 + 450), 1e-20);
}

TEST(Chi2, SidakCorrection) {
    EXPECT_NEAR(sidak_significance(0.01, 1), 0.01, 1e-15);
    const double s = sidak_significance(0.01, 20);
    EXPECT_NEAR(1 - std::pow(1 - s, 20), 0.01, 1e-12);
}

// The remaining tests make sure the machinery can fail: a test that cannot fail checks
// nothing.
TEST(Chi2, CorrectDensityPasses) {
    SphereChi2Options o;
    o.hemisphere = true;
    const Chi2Result r = chi2_sphere(
        [](Rng& rng) { return std::optional<Vec3>(square_to_cosine_hemisphere(next_2d(rng))); },
        [](Vec3 w) { return double(cosine_hemisphere_pdf(w)); }, o);
    EXPECT_TRUE(r.passed) << r.report;
    EXPECT_NEAR(r.pdf_integral, 1.0, 1e-5);
}

TEST(Chi2, UniformDensityForCosineSamplesFails) {
    SphereChi2Options o;
    o.hemisphere = true;
    const Chi2Result r = chi2_sphere(
        [](Rng& rng) { return std::optional<Vec3>(square_to_cosine_hemisphere(next_2d(rng))); },
        [](Vec3 w) { return double(uniform_hemisphere_pdf(w)); }, o);
    EXPECT_FALSE(r.passed) << r.report;
    EXPECT_LT(r.p_value, 1e-10);
    EXPECT_NE(r.report.find("worst cells"), std::string::npos);
}

// A pdf 3% too large everywhere: the statistic alone barely notices (the "no sample"
// cell's expectation is clamped at 0), the integral check does.
TEST(Chi2, PdfThatIntegratesAboveOneFails) {
    SphereChi2Options o;
    o.hemisphere = true;
    const Chi2Result r = chi2_sphere(
        [](Rng& rng) { return std::optional<Vec3>(square_to_cosine_hemisphere(next_2d(rng))); },
        [](Vec3 w) { return 1.03 * double(cosine_hemisphere_pdf(w)); }, o);
    EXPECT_NEAR(r.pdf_integral, 1.03, 1e-5);
    EXPECT_FALSE(r.passed) << r.report;
    EXPECT_NE(r.report.find("integrates to"), std::string::npos) << r.report;
}

TEST(Chi2, SlightlyWrongExponentFails) {
    // Samples from cos^1 against the normalized cos^1.2 lobe: a subtle error.
    SphereChi2Options o;
    o.hemisphere = true;
    const Chi2Result r = chi2_sphere(
        [](Rng& rng) { return std::optional<Vec3>(square_to_cosine_hemisphere(next_2d(rng))); },
        [](Vec3 w) { return w.z > 0 ? 2.2 / (2 * M_PI) * std::pow(double(w.z), 1.2) : 0.0; }, o);
    EXPECT_NEAR(r.pdf_integral, 1.0, 1e-5);
    EXPECT_FALSE(r.passed) << r.report;
}

TEST(Chi2, SamplesWhereThePdfIsZeroFail) {
    // Uniform sphere samples judged by the hemisphere density on the full sphere: half
    // of them land in cells of zero expectation.
    SphereChi2Options o;
    const Chi2Result r = chi2_sphere(
        [](Rng& rng) { return std::optional<Vec3>(square_to_uniform_sphere(next_2d(rng))); },
        [](Vec3 w) { return double(uniform_hemisphere_pdf(w)); }, o);
    EXPECT_FALSE(r.passed) << r.report;
    EXPECT_GT(r.invalid, 0u);
}

TEST(Chi2, LostSamplesMustMatchTheMissingMass) {
    // The sampler returns nothing half the time: a pdf integrating to 1/2 is right, a
    // pdf integrating to 1 is not.
    auto sample = [](Rng& rng) -> std::optional<Vec3> {
        if (rng.next_float() < 0.5f) return std::nullopt;
        return square_to_uniform_sphere(next_2d(rng));
    };
    SphereChi2Options o;
    const Chi2Result half = chi2_sphere(
        sample, [](Vec3) { return 0.5 / (4 * M_PI); }, o);
    EXPECT_TRUE(half.passed) << half.report;
    EXPECT_NEAR(double(half.lost) / o.samples, 0.5, 0.01);
    const Chi2Result full = chi2_sphere(
        sample, [](Vec3) { return 1 / (4 * M_PI); }, o);
    EXPECT_FALSE(full.passed) << full.report;
}

TEST(Chi2, OffDomainSamplesFail) {
    SphereChi2Options o;
    o.hemisphere = true;
    const Chi2Result r = chi2_sphere(
        [](Rng& rng) { return std::optional<Vec3>(square_to_uniform_sphere(next_2d(rng))); },
        [](Vec3 w) { return double(uniform_hemisphere_pdf(w)); }, o);
    EXPECT_FALSE(r.passed) << r.report;
    EXPECT_GT(r.invalid, 0u);
}

TEST(Chi2, PlanarUniformPassesAndWrongDensityFails) {
    PlanarChi2Options o;
    const Chi2Result ok = chi2_planar([](Rng& rng) { return std::optional<Vec2>(next_2d(rng)); },
                                      [](Vec2) { return 1.0; }, o);
    EXPECT_TRUE(ok.passed) << ok.report;
    EXPECT_NEAR(ok.pdf_integral, 1.0, 1e-6);
    // A linear ramp in x is a mild error: it must still be caught.
    const Chi2Result bad = chi2_planar([](Rng& rng) { return std::optional<Vec2>(next_2d(rng)); },
                                       [](Vec2 p) { return 0.9 + 0.2 * p.x; }, o);
    EXPECT_FALSE(bad.passed) << bad.report;
}

}  // namespace
}  // namespace penumbra::test
