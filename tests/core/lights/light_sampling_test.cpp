// Chi-square tests of every non-delta light's sample_Li against its pdf_Li, and the
// discrete distributions that choose among lights and environment texels.
#include <gtest/gtest.h>

#include "core/lights/environment_light.h"
#include "core/lights/light_set.h"
#include "core/lights/triangle_light.h"
#include "core/sampling/alias_table.h"
#include "core/sampling/distribution.h"
#include "support/chi2.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

// Six tests of sampling in this file share the overall level.
const double kLevel = test::sidak_significance(0.01, 6);

// A small HDR sky with a bright sun, a dark band and a black row.
Image test_sky() {
    Image img(32, 16, 3);
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            float* p = img.at(x, y);
            const float v = y < 8 ? 1.0f + 0.1f * x : 0.2f;
            p[0] = v;
            p[1] = 0.8f * v;
            p[2] = y == 12 ? 0.0f : 0.5f * v;
            if (y == 12) p[0] = p[1] = 0;
        }
    float* sun = img.at(20, 4);
    sun[0] = sun[1] = sun[2] = 500;
    return img;
}

TEST(EnvironmentLight, ImageSamplingMatchesPdf) {
    for (float rotation : {77.0f}) {  // a rotation exercises both mappings
        const EnvironmentLight env(test_sky(), 2.0f, rotation, 1.0f);
        const ShadingPoint ref{{0, 0, 0}, {0, 1, 0}};
        test::SphereChi2Options opt;
        opt.significance = kLevel;
        const auto r = test::chi2_sphere(
            [&](Rng& rng) -> std::optional<Vec3> {
                const auto ls = env.sample_Li(ref, {rng.next_float(), rng.next_float()}, 0);
                if (!ls) return std::nullopt;
                // The returned pdf and radiance agree with pdf_Li and Le.
                EXPECT_NEAR(ls->pdf, env.pdf_Li(ref, ls->wi, 0), 1e-3f * ls->pdf);
                return ls->wi;
            },
            [&](Vec3 w) { return env.pdf_Li(ref, w, 0); }, opt);
        EXPECT_TRUE(r.passed) << r.report;
        EXPECT_NEAR(r.pdf_integral, 1.0, 1e-3);
    }
}

TEST(EnvironmentLight, DirectionAndTexelMappingRoundTrip) {
    const EnvironmentLight env(test_sky(), 1.0f, 33.0f, 1.0f);
    for (float u : {0.01f, 0.3f, 0.77f})
        for (float v : {0.05f, 0.5f, 0.93f}) {
            const Vec2 uv = env.direction_to_uv(env.uv_to_direction({u, v}));
            EXPECT_NEAR(uv.x, u, 1e-5f);
            EXPECT_NEAR(uv.y, v, 1e-5f);
        }
    // v = 0 is straight up (+Y).
    EXPECT_NEAR(env.uv_to_direction({0.3f, 0}).y, 1.0f, 1e-6f);
}

TEST(EnvironmentLight, ConstantSamplingIsUniform) {
    const EnvironmentLight env(Spectrum(1, 2, 3), 1.0f);
    const ShadingPoint ref{{0, 0, 0}, {0, 1, 0}};
    test::SphereChi2Options opt;
    opt.significance = kLevel;
    const auto r = test::chi2_sphere(
        [&](Rng& rng) -> std::optional<Vec3> {
            const auto ls = env.sample_Li(ref, {rng.next_float(), rng.next_float()}, 0);
            return ls ? std::optional<Vec3>(ls->wi) : std::nullopt;
        },
        [&](Vec3 w) { return env.pdf_Li(ref, w, 0); }, opt);
    EXPECT_TRUE(r.passed) << r.report;
}

TEST(TriangleLight, AreaSamplingMatchesSolidAnglePdf) {
    Scene scene;
    MaterialDesc m;
    m.emissive = Spectrum(3);
    scene.materials.push_back(m);
    // A large triangle close to the receiver: strongly non-uniform in solid angle.
    const uint32_t quad =
        test::add_quad_object(scene, {-1, 0.3f, -1}, {2, 0.3f, -1}, {2, 0.3f, 2}, {-1, 0.3f, 2}, 0);
    test::add_instance(scene, quad, Transform::rotate({0.1f, 0, 0.05f, 1}));
    const TriangleLight light(scene, 0, 0, 0, Spectrum(3), TriangleSampling::Area);
    const ShadingPoint ref{{0, 0, 0}, {0, 1, 0}};
    test::SphereChi2Options opt;
    opt.significance = kLevel;
    opt.cos_bins = 20;
    opt.phi_bins = 40;
    const auto r = test::chi2_sphere(
        [&](Rng& rng) -> std::optional<Vec3> {
            const auto ls = light.sample_Li(ref, {rng.next_float(), rng.next_float()}, 0);
            if (!ls) return std::nullopt;
            EXPECT_NEAR(ls->pdf, light.pdf_Li(ref, ls->wi, 0), 1e-3f * ls->pdf);
            EXPECT_EQ(ls->Li, Spectrum(3));
            return ls->wi;
        },
        [&](Vec3 w) { return light.pdf_Li(ref, w, 0); }, opt);
    EXPECT_TRUE(r.passed) << r.report;
    EXPECT_NEAR(r.pdf_integral, 1.0, 1e-2);
}

TEST(AliasTable, SamplesInProportionToWeights) {
    const std::vector<float> w = {1, 0, 3, 0.5f, 10, 0, 2.5f};
    const AliasTable table(w);
    std::vector<double> observed(w.size()), expected(w.size());
    const int n = 200000;
    Rng rng(5);
    for (int i = 0; i < n; ++i) {
        float pmf;
        const uint32_t k = table.sample(rng.next_float(), &pmf);
        EXPECT_FLOAT_EQ(pmf, table.pmf(k));
        observed[k] += 1;
    }
    for (size_t k = 0; k < w.size(); ++k) expected[k] = n * w[k] / 17.0;
    const auto r = test::chi2_compare(observed, expected, n, kLevel,
                                      [](size_t k) { return std::to_string(k); });
    EXPECT_TRUE(r.passed) << r.report;
    EXPECT_EQ(observed[1], 0);
    EXPECT_TRUE(AliasTable(std::vector<float>{0, 0}).empty());
}

// The remapped u serves as a further sample (sample_one_light places the light point
// with it): given each choice it must be uniform. Cells: (index, tenth of [0,1)).
TEST(AliasTable, RemappedUIsUniformGivenTheChoice) {
    const std::vector<float> w = {1, 0, 3, 0.5f, 10, 0, 2.5f};
    const AliasTable table(w);
    const size_t bins = 10;
    std::vector<double> observed(w.size() * bins), expected(w.size() * bins);
    const int n = 400000;
    Rng rng(7);
    for (int i = 0; i < n; ++i) {
        float u_remapped = -1;
        const uint32_t k = table.sample(rng.next_float(), nullptr, &u_remapped);
        ASSERT_GE(u_remapped, 0.0f);
        ASSERT_LT(u_remapped, 1.0f);
        observed[k * bins + std::min(size_t(u_remapped * bins), bins - 1)] += 1;
    }
    for (size_t c = 0; c < expected.size(); ++c) expected[c] = n * w[c / bins] / 17.0 / bins;
    const auto r = test::chi2_compare(observed, expected, n, kLevel, [&](size_t c) {
        return std::to_string(c / bins) + "/" + std::to_string(c % bins);
    });
    EXPECT_TRUE(r.passed) << r.report;
}

TEST(Distribution2D, PdfIntegratesToOneAndMatchesSamples) {
    std::vector<float> f(6 * 4);
    for (size_t i = 0; i < f.size(); ++i) f[i] = float((i * 7) % 5);  // includes zeros
    const Distribution2D d(f, 6, 4);
    test::PlanarChi2Options opt;
    opt.x_bins = 6;
    opt.y_bins = 4;
    const auto r = test::chi2_planar(
        [&](Rng& rng) -> std::optional<Vec2> {
            float pdf;
            const Vec2 p = d.sample({rng.next_float(), rng.next_float()}, &pdf);
            EXPECT_NEAR(pdf, d.pdf(p), 1e-4f * pdf);
            return p;
        },
        [&](Vec2 p) { return d.pdf(p); }, opt);
    EXPECT_TRUE(r.passed) << r.report;
    EXPECT_NEAR(r.pdf_integral, 1.0, 1e-4);
}

}  // namespace
}  // namespace penumbra
