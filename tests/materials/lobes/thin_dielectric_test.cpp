// Thin-walled dielectric sheets. Smooth: straight-through transmission (wi = -wo), the
// inter-reflection sum R' = 2R / (1 + R), R' + T' = 1. Rough: sampling against the pdf
// over the whole sphere from both sides and, folded, by half vector down to alpha 1e-3;
// eval/pdf agreement, reciprocity of reflection and transmission, and the furnace: reflection plus transmission is exactly the white
// mirror lobe (Cook-Torrance with F = 1), sample by sample.
#include "materials/lobes/thin_dielectric.h"

#include <gtest/gtest.h>

#include <sstream>

#include "materials/lobes/cook_torrance.h"
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
    p.masking = MaskingModel::SmithCorrelated;
    return p;
}

std::string describe(const DielectricParams& p, Vec3 wo) {
    std::ostringstream s;
    s << (p.distribution == MicrofacetType::Ggx ? "GGX" : "Beckmann") << ", eta " << p.eta
      << ", alpha " << p.alpha << ", wo.z " << wo.z;
    return s.str();
}

TEST(ThinDielectricBsdf, SheetReflectanceSumsInterReflections) {
    // Normal incidence on glass: R = 0.04 per interface, R' = 0.04 + 0.96^2 0.04 / (1 -
    // 0.04^2) = 0.0769..., from either side.
    EXPECT_NEAR(ThinDielectricBsdf::sheet_reflectance(1, 1.5f), 0.0769231f, 1e-6f);
    EXPECT_NEAR(ThinDielectricBsdf::sheet_reflectance(-1, 1.5f), 0.0769231f, 1e-6f);
    EXPECT_EQ(ThinDielectricBsdf::sheet_reflectance(0.7f, 1.0f), 0.0f);
    for (float c : {0.9f, 0.3f, 0.01f}) {
        const float R = fresnel_dielectric(c, 1.33f);
        EXPECT_NEAR(ThinDielectricBsdf::sheet_reflectance(c, 1.33f),
                    R + (1 - R) * (1 - R) * R / (1 - R * R), 1e-6f);
    }
}

TEST(ThinDielectricBsdf, SmoothTransmitsStraightThrough) {
    DielectricParams p = params(1.5f, 0);
    p.transmittance = {0.9f, 0.6f, 0.3f};
    const ThinDielectricBsdf bsdf(p);
    ASSERT_TRUE(bsdf.has_specular());
    for (float cos_o : {1.0f, 0.6f, 0.05f, -0.4f, -0.999f}) {
        const Vec3 wo = spherical_direction(cos_o, 0.8f);
        const float F = ThinDielectricBsdf::sheet_reflectance(cos_o, 1.5f);
        for (Transport mode : {Transport::Radiance, Transport::Importance}) {
            const auto r = bsdf.sample(wo, 0.999f * F, {0.5f, 0.5f}, mode);
            ASSERT_TRUE(r);
            EXPECT_EQ(r->wi, Vec3(-wo.x, -wo.y, wo.z));
            EXPECT_FLOAT_EQ(r->pdf, F);
            EXPECT_NEAR(r->weight().x, 1.0f, 1e-5f);
            const auto t = bsdf.sample(wo, F + 0.999f * (1 - F), {0.5f, 0.5f}, mode);
            ASSERT_TRUE(t);
            EXPECT_TRUE(t->is_specular());
            // Not bent: the direction the light had, and no eta^2 (same medium both sides).
            EXPECT_EQ(t->wi, -wo);
            EXPECT_EQ(t->eta, 1.0f);
            EXPECT_FLOAT_EQ(t->pdf, 1 - F);
            EXPECT_NEAR(t->weight().x, 0.9f, 1e-5f);
            EXPECT_NEAR(t->weight().z, 0.3f, 1e-5f);
        }
        // Untinted, R' + T' = 1: every sample weighs 1.
        const test::AlbedoEstimate a = test::directional_albedo(
            ThinDielectricBsdf(params(1.5f, 0)), wo, 5000, 3, Transport::Radiance);
        EXPECT_NEAR(a.mean.x, 1.0f, 1e-5f) << "cos_o " << cos_o;
        EXPECT_NEAR(a.std_error.x, 0.0f, 1e-6f);
    }
}

TEST(ThinDielectricBsdf, RoughSamplesFollowThePdf) {
    const MicrofacetType types[] = {MicrofacetType::Ggx, MicrofacetType::Beckmann};
    const float alphas[] = {0.05f, 0.3f, 1.0f};
    const float cos_os[] = {0.9f, 0.05f, -0.7f};
    test::BsdfChi2Options o;
    o.samples = 100000;
    o.significance =
        test::sidak_significance(0.01, 2 * std::size(alphas) * std::size(cos_os));
    int seed = 900;
    for (MicrofacetType type : types)
        for (float alpha : alphas)
            for (float cos_o : cos_os) {
                DielectricParams p = params(seed % 2 ? 1.5f : 1.0f, alpha, type);
                p.masking = seed % 3 ? MaskingModel::SmithCorrelated : MaskingModel::SmithSeparable;
                const ThinDielectricBsdf bsdf(p);
                const Vec3 wo = spherical_direction(cos_o, 0.4f);
                o.seed = ++seed;
                const test::Chi2Result r = test::bsdf_chi2_sphere(bsdf, wo, o);
                EXPECT_TRUE(r.passed) << describe(p, wo) << "\n" << r.report;
                const double lost = double(r.lost) / r.samples;
                EXPECT_NEAR(r.pdf_integral, 1 - lost, 5 * std::sqrt(lost / r.samples) + 2e-4)
                    << describe(p, wo);
            }
}

// The sheet with transmitted directions folded back through the surface plane: its two
// lobes then share one microfacet normal per direction, so the half-vector chi-square
// (reflection only) can bin lobes too narrow for the sphere.
class FoldedSheet final : public Bsdf {
public:
    explicit FoldedSheet(const ThinDielectricBsdf& sheet) : m_sheet(sheet) {}
    Spectrum eval(Vec3 wo, Vec3 wi, Transport mode) const override {
        return m_sheet.eval(wo, wi, mode) + m_sheet.eval(wo, {wi.x, wi.y, -wi.z}, mode);
    }
    float pdf(Vec3 wo, Vec3 wi, Transport mode) const override {
        return m_sheet.pdf(wo, wi, mode) + m_sheet.pdf(wo, {wi.x, wi.y, -wi.z}, mode);
    }
    std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Vec2 u, Transport mode) const override {
        std::optional<BsdfSample> s = m_sheet.sample(wo, u_lobe, u, mode);
        if (!s || s->wi.z * wo.z > 0) return s;
        s->wi.z = -s->wi.z;
        s->f = eval(wo, s->wi, mode);
        s->pdf = pdf(wo, s->wi, mode);
        return s;
    }
    bool has_specular() const override { return false; }

private:
    const ThinDielectricBsdf& m_sheet;
};

TEST(ThinDielectricBsdf, NarrowLobesFollowTheirPdf) {
    const float alphas[] = {1e-3f, 1e-2f};
    const float cos_os[] = {0.9f, 0.2f, 0.02f};
    test::BsdfChi2Options o;
    o.samples = 100000;
    o.significance = test::sidak_significance(0.01, 2 * std::size(alphas) * std::size(cos_os));
    int seed = 950;
    for (MicrofacetType type : {MicrofacetType::Ggx, MicrofacetType::Beckmann})
        for (float alpha : alphas)
            for (float cos_o : cos_os) {
                const DielectricParams p = params(1.5f, alpha, type);
                const ThinDielectricBsdf sheet(p);
                const FoldedSheet folded(sheet);
                const Vec3 wo = spherical_direction(cos_o, 0.9f);
                o.seed = ++seed;
                const test::Chi2Result r = test::bsdf_chi2_half_vector(folded, wo, alpha, 0, o);
                EXPECT_TRUE(r.passed) << describe(p, wo) << "\n" << r.report;
            }
}

TEST(ThinDielectricBsdf, RoughSampleAgreesWithEvalPdfAndIsReciprocal) {
    Rng rng(31);
    for (int i = 0; i < 200; ++i) {
        DielectricParams p = params(i % 3 ? 1.5f : 1.33f, 0.02f + rng.next_float(),
                                    i % 2 ? MicrofacetType::Beckmann : MicrofacetType::Ggx);
        p.transmittance = {0.9f, 0.5f, 0.2f};
        const ThinDielectricBsdf bsdf(p);
        const Vec3 wo = test::random_direction(rng, 0.02f, i % 5 == 0);
        const Transport mode = i % 2 ? Transport::Radiance : Transport::Importance;
        EXPECT_EQ(test::check_sample_agreement(bsdf, wo, 50, i, mode), "") << describe(p, wo);
        if (i % 20 == 0) {
            EXPECT_EQ(test::check_reciprocity(bsdf, 100, i), "") << describe(p, wo);
        }
        // Transmission is reciprocal too (no eta^2: the same medium on both sides).
        const Vec3 a = test::random_direction(rng, 0.02f), b = test::random_direction(rng, 0.02f, true);
        const Spectrum fab = bsdf.eval(a, b, Transport::Radiance);
        const Spectrum fba = bsdf.eval(b, a, Transport::Radiance);
        EXPECT_NEAR(fab.x, fba.x, 1e-4f * fab.x) << describe(p, a);
        EXPECT_EQ(fab, bsdf.eval(a, b, Transport::Importance));
    }
}

TEST(ThinDielectricBsdf, ReflectionPlusTransmissionIsTheWhiteMirrorLobe) {
    // R' + T' = 1 on every microfacet, so for the same (u_lobe, u) either choice weighs
    // what the white Cook-Torrance mirror (F = 1) weighs: the sheet loses exactly what
    // single-scattering microfacets lose, and gains nothing.
    for (MicrofacetType type : {MicrofacetType::Ggx, MicrofacetType::Beckmann})
        for (float alpha : {1e-3f, 0.2f, 0.6f, 1.0f})
            for (float cos_o : {1.0f, 0.4f, 0.03f}) {
                const DielectricParams p = params(1.5f, alpha, type);
                const ThinDielectricBsdf sheet(p);
                CookTorranceParams cp;
                cp.distribution = type;
                cp.alpha = alpha;
                const CookTorranceBsdf mirror(cp);
                const Vec3 wo = spherical_direction(cos_o, 1.1f);
                Rng rng(77);
                for (int k = 0; k < 200; ++k) {
                    const Vec2 u(rng.next_float(), rng.next_float());
                    const auto m = mirror.sample(wo, 0.5f, u, Transport::Radiance);
                    const auto r = sheet.sample(wo, 0, u, Transport::Radiance);
                    const auto t = sheet.sample(wo, 0x1.fffffep-1f, u, Transport::Radiance);
                    ASSERT_EQ(bool(m), bool(r)) << describe(p, wo);
                    ASSERT_EQ(bool(m), bool(t)) << describe(p, wo);
                    if (!m) continue;
                    EXPECT_NEAR(r->weight().x, m->weight().x, 2e-4f * m->weight().x);
                    EXPECT_NEAR(t->weight().x, m->weight().x, 2e-4f * m->weight().x);
                    EXPECT_NEAR(t->wi.z, -r->wi.z, 1e-6f);
                }
                const test::AlbedoEstimate a =
                    test::directional_albedo(sheet, wo, 20000, 12, Transport::Importance);
                const test::AlbedoEstimate b =
                    test::directional_albedo(mirror, wo, 20000, 12, Transport::Importance);
                EXPECT_LE(a.mean.x, 1 + 3 * a.std_error.x + 1e-5f) << describe(p, wo);
                // The same random numbers: equal to float rounding, not just within noise.
                EXPECT_NEAR(a.mean.x, b.mean.x, 2e-4f * b.mean.x) << describe(p, wo);
                if (alpha == 1e-3f) {
                    EXPECT_NEAR(a.mean.x, 1.0f, 1e-3f) << describe(p, wo);
                }
            }
}

}  // namespace
}  // namespace penumbra
