// KHR_materials_anisotropy in the glTF BRDF (materials/metal_rough_bsdf.h) and its
// albedo table (materials/albedo/anisotropy_albedo.h): sampling against the pdf (also lobes
// too narrow to bin by direction), sample/eval/pdf agreement, reciprocity, the white
// furnace, and the spec's limits (strength 0, roughness 1).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "materials/albedo/anisotropy_albedo.h"
#include "materials/metal_rough_bsdf.h"
#include "materials/albedo/specular_albedo.h"
#include "support/bsdf/bsdf_checks.h"
#include "support/bsdf/bsdf_properties.h"

namespace penumbra {
namespace {

using test::spherical_direction;

MetalRoughParams params(float roughness, float strength, float metallic) {
    MetalRoughParams p;
    p.base_color = {0.8f, 0.6f, 0.3f};
    p.metallic = metallic;
    p.alpha = roughness * roughness;
    p.anisotropy = strength;
    return p;
}

std::string describe(const MetalRoughParams& p, Vec3 wo) {
    std::ostringstream s;
    s << "alpha " << p.alpha << ", strength " << p.anisotropy << ", metallic " << p.metallic
      << ", base " << p.base_color.x << ", wo (" << wo.x << ", " << wo.y << ", " << wo.z << ")";
    return s.str();
}

// The table's worst interpolation error, measured by TableMatchesBruteForce below (0.0056
// for GGX; the isotropic table's is 1.2e-3): a white dielectric reflects
// 1 + (E_true - E_table)(wo).
constexpr float kAnisoTableTolerance = 0.01f;

TEST(AnisotropyAlbedo, TableMatchesBruteForce) {
    // Off the grid's nodes in all four coordinates, half of them near the hard corner
    // (smooth, strongly stretched lobes seen at grazing angles).
    Rng rng(17);
    float worst = 0;
    for (int n = 0; n < 80; ++n) {
        const bool corner = n % 2;
        const float r = corner ? 0.01f + 0.2f * rng.next_float() : rng.next_float();
        const float s = corner ? 0.7f + 0.3f * rng.next_float() : rng.next_float();
        const float mu = corner ? 0.005f + 0.1f * rng.next_float() : 0.005f + 0.995f * rng.next_float();
        const float phi = 2 * kPi * rng.next_float();
        const Vec3 w = spherical_direction(mu, phi);
        const Vec2 a = anisotropic_alphas(r * r, s);
        const Vec2 exact = integrate_specular_albedo(
            MicrofacetDistribution(MicrofacetType::Ggx, a.x, a.y), w, 96, 160);
        const Vec2 table = AnisotropicSpecularAlbedo(MicrofacetType::Ggx, r * r, s).at(w);
        worst = std::max({worst, std::abs(table.x - exact.x), std::abs(table.y - exact.y)});
        EXPECT_NEAR(table.x, exact.x, kAnisoTableTolerance) << "r " << r << " s " << s << " mu " << mu;
        EXPECT_NEAR(table.y, exact.y, kAnisoTableTolerance) << "r " << r << " s " << s << " mu " << mu;
    }
    std::printf("anisotropic GGX: worst table error %.5f\n", worst);
}

TEST(AnisotropyAlbedo, AverageIsTheCosineWeightedIntegralOfTheInterpolant) {
    for (float r : {0.0f, 0.2f, 0.55f, 1.0f})
        for (float s : {0.0f, 0.4f, 1.0f}) {
            const AnisotropicSpecularAlbedo albedo(MicrofacetType::Ggx, r * r, s);
            // Midpoint rule in (mu, phi): (1/pi) int (A, B) mu dmu dphi.
            const int nm = 2000, np = 400;
            double a = 0, b = 0;
            for (int i = 0; i < nm; ++i)
                for (int l = 0; l < np; ++l) {
                    const float mu = (i + 0.5f) / nm, phi = 2 * kPi * (l + 0.5f) / np;
                    const Vec2 ab = albedo.at(spherical_direction(mu, phi));
                    a += ab.x * mu;
                    b += ab.y * mu;
                }
            const double scale = 2.0 / (double(nm) * np);  // (1/pi) dmu dphi, with dphi = 2 pi / np
            EXPECT_NEAR(albedo.average().x, a * scale, 1e-4) << "r " << r << " s " << s;
            EXPECT_NEAR(albedo.average().y, b * scale, 1e-4) << "r " << r << " s " << s;
        }
}

TEST(MetalRoughAnisotropy, SamplesFollowThePdf) {
    const float roughness[] = {0.3f, 0.7f};
    const float strength[] = {0.5f, 1.0f};
    const float metallic[] = {0.0f, 1.0f};
    const float cos_os[] = {1.0f, 0.5f, 0.05f};
    const float phis[] = {0.3f, 1.4f};
    const int tests = 2 * 2 * 2 * 3 * 2;
    test::BsdfChi2Options o;
    o.samples = 100000;
    o.significance = test::sidak_significance(0.01, tests);
    int seed = 100;
    for (float r : roughness)
        for (float s : strength)
            for (float m : metallic)
                for (float cos_o : cos_os)
                    for (float phi : phis) {
                        const MetalRoughParams p = params(r, s, m);
                        const MetalRoughBsdf bsdf(p);
                        const Vec3 wo = spherical_direction(cos_o, phi);
                        o.seed = ++seed;
                        const test::Chi2Result res = test::bsdf_chi2(bsdf, wo, o);
                        EXPECT_TRUE(res.passed) << describe(p, wo) << "\n" << res.report;
                    }
}

TEST(MetalRoughAnisotropy, NarrowLobesFollowTheirPdf) {
    // Roughness 0 and 0.1 with strength 1 and 0.3: 1 x 1e-4 and 0.09 x 1e-4 lobes, a line
    // across the sphere; binned by their stretched half vectors. Metal only: the disk
    // would not see the diffuse base.
    const Vec2 cases[] = {{0.0f, 1.0f}, {0.0f, 0.3f}, {0.1f, 1.0f}, {0.1f, 0.3f}};
    const float cos_os[] = {1.0f, 0.4f, 0.03f};
    const int tests = 4 * 3;
    test::BsdfChi2Options o;
    o.samples = 100000;
    o.significance = test::sidak_significance(0.01, tests);
    int seed = 200;
    for (Vec2 c : cases)
        for (float cos_o : cos_os) {
            const MetalRoughParams p = params(c.x, c.y, 1.0f);
            const MetalRoughBsdf bsdf(p);
            ASSERT_FALSE(bsdf.has_specular());
            const Vec3 wo = spherical_direction(cos_o, 0.6f);
            o.seed = ++seed;
            const test::Chi2Result res = test::bsdf_chi2_half_vector(
                bsdf, wo, anisotropic_alphas(p.alpha, p.anisotropy), 0, o);
            EXPECT_TRUE(res.passed) << describe(p, wo) << "\n" << res.report;
        }
}

TEST(MetalRoughAnisotropy, SampleAgreesWithEvalAndPdf) {
    Rng rng(9);
    for (int i = 0; i < 300; ++i) {
        const float r = i % 7 == 0 ? 0.0f : rng.next_float(), s = rng.next_float();
        const MetalRoughParams p = params(r, s, rng.next_float());
        const Vec3 wo = test::random_direction(rng, 0.01f);
        const std::string err =
            test::check_sample_agreement(MetalRoughBsdf(p), wo, 50, 10 + i, Transport::Radiance);
        EXPECT_EQ(err, "") << describe(p, wo);
    }
}

TEST(MetalRoughAnisotropy, Reciprocity) {
    Rng rng(10);
    for (int i = 0; i < 200; ++i) {
        const float r = i % 5 == 0 ? 0.0f : rng.next_float();
        const MetalRoughParams p = params(r, rng.next_float(), rng.next_float());
        EXPECT_EQ(test::check_reciprocity(MetalRoughBsdf(p), 20, 30 + i), "") << describe(p, {});
    }
}

TEST(MetalRoughAnisotropy, HighlightStretchesAlongTheTangent) {
    // Light from the normal, seen 40 degrees off it: a metal with strength 1 along x
    // reflects far more towards x than towards y, and an isotropic one equally.
    const Vec3 wi(0, 0, 1);
    const MetalRoughBsdf aniso(params(0.3f, 1.0f, 1.0f)), iso(params(0.3f, 0.0f, 1.0f));
    const Vec3 along_x = spherical_direction(0.766f, 0), along_y = spherical_direction(0.766f, kPi / 2);
    EXPECT_GT(aniso.eval(along_x, wi, Transport::Radiance).x,
              10 * aniso.eval(along_y, wi, Transport::Radiance).x);
    EXPECT_FLOAT_EQ(iso.eval(along_x, wi, Transport::Radiance).x,
                    iso.eval(along_y, wi, Transport::Radiance).x);
}

TEST(MetalRoughAnisotropy, NoEffectAtRoughnessOne) {
    // At roughness 1 alpha_t = mix(1, 1, s^2) = 1, so the lobe is the isotropic one (the
    // spec: "no effect"), the base up to the two tables' errors.
    Rng rng(11);
    for (int i = 0; i < 500; ++i) {
        const Vec3 wo = test::random_direction(rng), wi = test::random_direction(rng);
        const float metallic = rng.next_float();
        const MetalRoughBsdf rough(params(1, 0, metallic)), stretched(params(1, 0.8f, metallic));
        const Spectrum a = rough.eval(wo, wi, Transport::Radiance);
        const Spectrum b = stretched.eval(wo, wi, Transport::Radiance);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(b[c], a[c], 0.02f * a[c] + 1e-6f);
        EXPECT_NEAR(stretched.pdf(wo, wi, Transport::Radiance), rough.pdf(wo, wi, Transport::Radiance),
                    0.02f * rough.pdf(wo, wi, Transport::Radiance));
    }
}

TEST(MetalRoughAnisotropy, AnisotropicLobesAreGgxUnderTheBeckmannSwitch) {
    // --microfacet beckmann compares isotropic lobes; anisotropic ones stay GGX (and need
    // no Beckmann table, whose integration takes ~45 s).
    Rng rng(12);
    MetalRoughParams ggx = params(0.4f, 0.6f, 0.3f), beckmann = ggx;
    beckmann.distribution = MicrofacetType::Beckmann;
    const MetalRoughBsdf a(ggx), b(beckmann);
    for (int i = 0; i < 100; ++i) {
        const Vec3 wo = test::random_direction(rng), wi = test::random_direction(rng);
        EXPECT_EQ(a.eval(wo, wi, Transport::Radiance), b.eval(wo, wi, Transport::Radiance));
        EXPECT_EQ(a.pdf(wo, wi, Transport::Radiance), b.pdf(wo, wi, Transport::Radiance));
    }
}

// White furnace: a white anisotropic dielectric reflects 1 up to the table's error (as
// the isotropic one does), and never more; a white metal reflects exactly the lobe's
// single-scattering albedo A(wo) by brute-force quadrature, so it never gains and loses
// only what the microfacet model loses (which, viewed along the smooth axis at grazing
// angles, can exceed the isotropic lobe's at either alpha: the 1 x 1e-4 lobe is a
// profile of grooves seen head-on there, and reflects 0.535 at every cos(theta_o)).
TEST(MetalRoughAnisotropy, WhiteFurnace) {
    float worst_gain = -1, worst_loss = 0;
    for (float r : {0.0f, 0.05f, 0.3f, 0.7f, 1.0f})
        for (float s : {0.3f, 0.7f, 1.0f})
            for (float cos_o : {1.0f, 0.7f, 0.3f, 0.05f, 0.01f})
                for (float phi : {0.0f, 0.8f, 1.5707964f}) {
                    const Vec3 wo = spherical_direction(cos_o, phi);
                    MetalRoughParams p = params(r, s, 0);
                    p.base_color = Spectrum(1);
                    const test::AlbedoEstimate d =
                        test::directional_albedo(MetalRoughBsdf(p), wo, 20000, 13);
                    const float sigma_d = 3 * d.std_error.x + 1e-5f;
                    EXPECT_LE(d.mean.x, 1 + sigma_d + kAnisoTableTolerance)
                        << describe(p, wo) << ": albedo " << d.mean.x;
                    EXPECT_GE(d.mean.x, 1 - sigma_d - kAnisoTableTolerance)
                        << describe(p, wo) << ": albedo " << d.mean.x;
                    worst_gain = std::max(worst_gain, d.mean.x - 1);
                    worst_loss = std::max(worst_loss, 1 - d.mean.x);

                    p.metallic = 1;
                    const test::AlbedoEstimate m =
                        test::directional_albedo(MetalRoughBsdf(p), wo, 20000, 14);
                    const Vec2 a = anisotropic_alphas(p.alpha, s);
                    const float lobe = integrate_specular_albedo(
                        MicrofacetDistribution(MicrofacetType::Ggx, a.x, a.y),
                        spherical_direction(std::max(cos_o, 1e-4f), phi), 64, 128).x;
                    EXPECT_NEAR(m.mean.x, lobe, 3 * m.std_error.x + 2e-3f)
                        << describe(p, wo) << ": albedo " << m.mean.x << ", the lobe's " << lobe;
                    EXPECT_LE(m.mean.x, 1 + 3 * m.std_error.x + 1e-5f) << describe(p, wo);
                }
    std::printf("anisotropic white dielectric: worst gain %.4f, worst loss %.4f\n", worst_gain,
                worst_loss);
}

}  // namespace
}  // namespace penumbra
