// Chi-square tests of every non-delta light's sample_Li against its pdf_Li, and the
// discrete distributions that choose among lights and environment texels.
#include <gtest/gtest.h>

#include "core/lights/environment_light.h"
#include "core/lights/light_set.h"
#include "core/lights/triangle_light.h"
#include "core/sampling/alias_table.h"
#include "core/sampling/distribution.h"
#include "support/statistics/chi2.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

// Seven chi-square tests in this file (two in one loop) share the overall level.
const double kLevel = test::sidak_significance(0.01, 7);

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

// Both distributions of an image (EnvironmentSampling): sample_Li follows pdf_Li, with
// the same pdf and radiance as pdf_Li and Le return. The compensated one follows
// luminance less the mean, so no sample goes below it.
TEST(EnvironmentLight, ImageSamplingMatchesPdf) {
    for (EnvironmentSampling sampling :
         {EnvironmentSampling::Full, EnvironmentSampling::MisCompensated}) {
        // A rotation exercises both mappings.
        const EnvironmentLight env(test_sky(), 2.0f, 77.0f, 1.0f, sampling);
        ASSERT_EQ(env.sampling(), sampling);
        const ShadingPoint ref{{0, 0, 0}, {0, 1, 0}};
        test::SphereChi2Options opt;
        opt.significance = kLevel;
        const auto r = test::chi2_sphere(
            [&](Rng& rng) -> std::optional<Vec3> {
                const auto ls = env.sample_Li(ref, {rng.next_float(), rng.next_float()}, 0);
                if (!ls) return std::nullopt;
                EXPECT_NEAR(ls->pdf, env.pdf_Li(ref, ls->wi, 0), 1e-3f * ls->pdf);
                return ls->wi;
            },
            [&](Vec3 w) { return env.pdf_Li(ref, w, 0); }, opt);
        EXPECT_TRUE(r.passed) << r.report;
        EXPECT_NEAR(r.pdf_integral, 1.0, 1e-3);
    }
}

// Which texels the compensated distribution keeps: test_sky's mean luminance over the
// sphere lies between its dark lower half (0.2) and its bright upper half (1 to 4.1 plus
// the sun), so the lower half gets density 0 and the sun the most; the power, which the
// light set chooses lights by, is the full image's either way.
TEST(EnvironmentLight, CompensatedDensityIsLuminanceAboveTheMean) {
    const Image sky = test_sky();
    const EnvironmentLight full(sky, 2.0f, 0.0f, 1.0f);
    const EnvironmentLight comp(sky, 2.0f, 0.0f, 1.0f, EnvironmentSampling::MisCompensated);
    EXPECT_EQ(full.sampling(), EnvironmentSampling::Full);
    EXPECT_FLOAT_EQ(comp.power(), full.power());
    const ShadingPoint ref{{0, 0, 0}, {0, 1, 0}};
    auto texel_dir = [&](int x, int y) {
        return full.uv_to_direction({(x + 0.5f) / sky.width, (y + 0.5f) / sky.height});
    };
    // The mean as the constructor weighs it: luminance times sin(theta), over sin(theta).
    double weighted = 0, weights = 0;
    for (int y = 0; y < sky.height; ++y)
        for (int x = 0; x < sky.width; ++x) {
            const double st = std::sin(kPi * (y + 0.5) / sky.height);
            weighted += luminance(sky.rgba(x, y).xyz()) * st;
            weights += st;
        }
    const float mean = float(weighted / weights);
    ASSERT_GT(mean, 0.2f);
    ASSERT_LT(mean, 1.0f + 0.1f * 31);
    for (int y = 0; y < sky.height; ++y)
        for (int x = 0; x < sky.width; ++x) {
            const float above = luminance(sky.rgba(x, y).xyz()) - mean;
            const float pdf = comp.pdf_Li(ref, texel_dir(x, y), 0);
            if (above > 1e-3f)
                EXPECT_GT(pdf, 0) << x << " " << y;
            else if (above < -1e-3f)
                EXPECT_EQ(pdf, 0) << x << " " << y;
        }
    // Density ratios between kept texels follow luminance less the mean, not luminance.
    const float sun = comp.pdf_Li(ref, texel_dir(20, 4), 0),
                sky_b = comp.pdf_Li(ref, texel_dir(30, 4), 0);
    const float expect =
        (luminance(sky.rgba(20, 4).xyz()) - mean) / (luminance(sky.rgba(30, 4).xyz()) - mean);
    EXPECT_NEAR(sun / sky_b, expect, 1e-3f * expect);
}

// A constant map has nothing above its mean: it keeps the full distribution, which is
// uniform over the sphere's area (sin(theta) in the image).
TEST(EnvironmentLight, ConstantMapKeepsTheFullDistribution) {
    Image flat(16, 8, 3);
    for (int y = 0; y < flat.height; ++y)
        for (int x = 0; x < flat.width; ++x)
            for (int c = 0; c < 3; ++c) flat.at(x, y)[c] = 0.5f;
    const EnvironmentLight env(flat, 1.0f, 0.0f, 1.0f, EnvironmentSampling::MisCompensated);
    EXPECT_EQ(env.sampling(), EnvironmentSampling::Full);
    const ShadingPoint ref{{0, 0, 0}, {0, 1, 0}};
    // At a row's centre the piecewise-constant density is the uniform one, but for the
    // midpoint rule's error in the rows' sum of sin(theta) (0.6% with 8 rows).
    const Vec3 w = env.uv_to_direction({0.3f, 3.5f / 8});
    EXPECT_NEAR(env.pdf_Li(ref, w, 0), 1 / (4 * kPi), 1e-2f / (4 * kPi));
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
