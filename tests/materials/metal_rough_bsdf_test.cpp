#include "materials/metal_rough_bsdf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <sstream>
#include <string>

#include "core/sampling/warp.h"
#include "materials/lobes/fresnel.h"
#include "support/bsdf/bsdf_checks.h"

namespace penumbra {
namespace {

using test::spherical_direction;

const float kRoughness[] = {0.05f, 0.3f, 0.7f, 1.0f};
const float kMetallic[] = {0.0f, 0.5f, 1.0f};
const float kCosOs[] = {1.0f, 0.7f, 0.3f, 0.05f};

// Base colours and KHR_materials_specular / _ior variants, in both layerings.
MetalRoughParams params(int variant, float roughness, float metallic) {
    MetalRoughParams p;
    p.alpha = roughness * roughness;
    p.metallic = metallic;
    p.layering = (variant / 4) % 2 ? GltfLayering::Spec : GltfLayering::AlbedoScaled;
    switch (variant % 4) {
        case 0:  // glTF defaults: ior 1.5, specular 1
            p.base_color = {0.8f, 0.6f, 0.3f};
            break;
        case 1:  // ior 1.8 with a coloured specularColor
            p.base_color = {0.9f, 0.9f, 0.9f};
            p.dielectric_f0 = Spectrum(1.0f, 0.6f, 0.3f) * f0_from_ior(1.8f);
            break;
        case 2:  // specular 0.5
            p.base_color = {0.2f, 0.5f, 0.9f};
            p.dielectric_f0 = Spectrum(0.5f * 0.04f);
            p.dielectric_f90 = 0.5f;
            break;
        default:  // specular 0: the dielectric is purely diffuse
            p.base_color = {0.7f, 0.3f, 0.5f};
            p.dielectric_f0 = Spectrum(0);
            p.dielectric_f90 = 0;
            break;
    }
    return p;
}

std::string describe(const MetalRoughParams& p, Vec3 wo) {
    std::ostringstream s;
    s << "alpha " << p.alpha << ", metallic " << p.metallic << ", f0 " << p.dielectric_f0.x << " "
      << p.dielectric_f0.y << " " << p.dielectric_f0.z << ", f90 " << p.dielectric_f90 << ", base "
      << p.base_color.x << " " << p.base_color.y << " " << p.base_color.z << ", layering "
      << (p.layering == GltfLayering::Spec ? "spec" : "albedo-scaled") << ", wo.z " << wo.z;
    return s.str();
}

// The Fresnel mix of the specular lobe, written out from the glTF spec.
Spectrum expected_fresnel(const MetalRoughParams& p, float c) {
    return fresnel_schlick(p.dielectric_f0, p.dielectric_f90, c) * (1 - p.metallic) +
           fresnel_schlick(p.base_color, 1, c) * p.metallic;
}

void expect_relative(Spectrum a, Spectrum b, float tol, const std::string& what) {
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(a[c], b[c], tol * std::max(std::abs(b[c]), 1e-6f)) << what;
}

TEST(MetalRoughBsdf, SamplesFollowThePdf) {
    const int tests = std::size(kRoughness) * std::size(kMetallic) * std::size(kCosOs);
    test::BsdfChi2Options o;
    o.samples = 100000;
    o.significance = test::sidak_significance(0.01, tests);
    int variant = 0;
    for (float roughness : kRoughness)
        for (float metallic : kMetallic)
            for (float cos_o : kCosOs) {
                const MetalRoughParams p = params(variant++, roughness, metallic);
                const MetalRoughBsdf bsdf(p);
                const Vec3 wo = spherical_direction(cos_o, 2.5f);
                o.seed = 41 + variant;
                const test::Chi2Result r = test::bsdf_chi2(bsdf, wo, o);
                EXPECT_TRUE(r.passed) << describe(p, wo) << "\n" << r.report;
                EXPECT_LE(r.pdf_integral, 1 + 1e-4) << describe(p, wo);
            }
}

TEST(MetalRoughBsdf, MirrorSamplesCarryFresnelOverLobeProbability) {
    // Roughness 0: the specular lobe is a delta; what remains must still match pdf(),
    // which then integrates to 1 - P(specular).
    test::BsdfChi2Options o;
    o.samples = 100000;
    o.significance = test::sidak_significance(0.01, 2 * std::size(kCosOs));
    int variant = 0;
    for (float metallic : kMetallic)
        for (float cos_o : kCosOs) {
            const MetalRoughParams p = params(variant++, 0.0f, metallic);
            const MetalRoughBsdf bsdf(p);
            ASSERT_TRUE(bsdf.has_specular());
            const Vec3 wo = spherical_direction(cos_o, -0.8f);
            const std::string what = describe(p, wo);
            Rng rng(50 + variant);
            float p_specular = -1;
            int specular = 0;
            const int n = 20000;
            for (int i = 0; i < n; ++i) {
                const auto s =
                    bsdf.sample(wo, rng.next_float(), {rng.next_float(), rng.next_float()},
                                Transport::Radiance);
                ASSERT_TRUE(s) << what;
                if (!s->is_specular()) {
                    // The diffuse base: value and density as eval() and pdf() give them.
                    expect_relative(s->f, bsdf.eval(wo, s->wi, Transport::Radiance), 1e-6f, what);
                    EXPECT_NEAR(s->pdf, bsdf.pdf(wo, s->wi, Transport::Radiance), 1e-6f * s->pdf);
                    continue;
                }
                ++specular;
                EXPECT_EQ(s->wi, Vec3(-wo.x, -wo.y, wo.z)) << what;
                ASSERT_GT(s->pdf, 0.0f) << what;
                ASSERT_LE(s->pdf, 1.0f) << what;
                if (p_specular < 0) p_specular = s->pdf;
                EXPECT_EQ(s->pdf, p_specular) << what;
                expect_relative(s->weight(), expected_fresnel(p, wo.z) / s->pdf, 1e-5f, what);
            }
            if (specular == 0) {
                // Only a layer without Fresnel reflection (specular 0) has no mirror lobe.
                EXPECT_TRUE(is_black(expected_fresnel(p, wo.z))) << what;
                p_specular = 0;
            }
            // The lobe is chosen with the probability it reports.
            const double sigma = std::sqrt(p_specular * (1 - p_specular) / n);
            EXPECT_NEAR(double(specular) / n, p_specular, 5 * sigma + 1e-9) << what;
            if (metallic == 1.0f) {
                EXPECT_EQ(specular, n) << what;  // no diffuse base left to sample
                continue;
            }
            o.seed = 60 + variant;
            const test::Chi2Result r = test::bsdf_chi2(bsdf, wo, o);
            EXPECT_TRUE(r.passed) << what << "\n" << r.report;
            EXPECT_NEAR(r.pdf_integral, 1 - p_specular, 1e-4) << what;
        }
}

TEST(MetalRoughBsdf, SampleAgreesWithEvalAndPdf) {
    Rng rng(7);
    for (int i = 0; i < 4000; ++i) {
        const MetalRoughParams p = params(i, 0.02f + 0.98f * rng.next_float(), rng.next_float());
        const MetalRoughBsdf bsdf(p);
        const Vec3 wo = spherical_direction(0.02f + 0.98f * rng.next_float(), 6 * rng.next_float());
        const auto s = bsdf.sample(wo, rng.next_float(), {rng.next_float(), rng.next_float()},
                                   Transport::Radiance);
        if (!s) continue;  // a microfacet reflection below the horizon
        ASSERT_FALSE(s->is_specular());
        ASSERT_GT(s->wi.z, 0.0f);
        const std::string what = describe(p, wo);
        expect_relative(s->f, bsdf.eval(wo, s->wi, Transport::Radiance), 1e-6f, what);
        EXPECT_NEAR(s->pdf, bsdf.pdf(wo, s->wi, Transport::Radiance), 1e-6f * s->pdf) << what;
    }
}

// The BSDF keeps wo's terms between calls and sample() evaluates f and pdf together:
// neither may change a value. One object asked about interleaved wo's (and sampled)
// answers bit for bit what a fresh object answers each time, and a sample's f and pdf,
// like eval_pdf()'s (the light sample's MIS), are eval's and pdf's exactly; over both
// layerings, both distributions, anisotropy, films, mirrors, metals and the bare
// Lambertian base.
TEST(MetalRoughBsdf, KeptWoTermsChangeNoValue) {
    Rng rng(29);
    for (int i = 0; i < 210; ++i) {
        const float roughness = i % 10 == 0 ? 0.0f : 0.02f + 0.98f * rng.next_float();
        MetalRoughParams p = params(i, roughness, i % 3 == 0 ? 1.0f : rng.next_float());
        if (i % 5 == 1) p.distribution = MicrofacetType::Beckmann;
        if (i % 7 == 2) p.anisotropy = rng.next_float();
        if (i % 6 == 3) {
            p.iridescence = rng.next_float();
            p.film.thickness = 100 + 800 * rng.next_float();
        }
        const MetalRoughBsdf kept(p);
        Vec3 wos[3], wis[3];
        for (int k = 0; k < 3; ++k) {
            wos[k] = spherical_direction(0.02f + 0.98f * rng.next_float(), 6 * rng.next_float());
            wis[k] = spherical_direction(0.02f + 0.98f * rng.next_float(), 6 * rng.next_float());
        }
        for (int q = 0; q < 9; ++q) {
            const Vec3 wo = wos[(q * 5) % 3], wi = wis[q % 3];
            const std::string what = describe(p, wo) + ", query " + std::to_string(q);
            const MetalRoughBsdf fresh(p), fresh2(p), fresh3(p);
            const Spectrum f = kept.eval(wo, wi, Transport::Radiance);
            const Spectrum f_ref = fresh.eval(wo, wi, Transport::Radiance);
            ASSERT_EQ(f.x, f_ref.x) << what;
            ASSERT_EQ(f.y, f_ref.y) << what;
            ASSERT_EQ(f.z, f_ref.z) << what;
            ASSERT_EQ(kept.pdf(wo, wi, Transport::Radiance),
                      fresh2.pdf(wo, wi, Transport::Radiance)) << what;
            for (const Vec3 w : {wi, Vec3(wi.x, wi.y, -wi.z)}) {  // and below the horizon
                const MetalRoughBsdf fresh6(p), fresh7(p);
                float pdf_both;
                const Spectrum f_both = kept.eval_pdf(wo, w, Transport::Radiance, &pdf_both);
                const Spectrum f_alone = fresh6.eval(wo, w, Transport::Radiance);
                ASSERT_EQ(f_both.x, f_alone.x) << what;
                ASSERT_EQ(f_both.y, f_alone.y) << what;
                ASSERT_EQ(f_both.z, f_alone.z) << what;
                ASSERT_EQ(pdf_both, fresh7.pdf(wo, w, Transport::Radiance)) << what;
            }
            const float u_lobe = rng.next_float();
            const Vec2 u(rng.next_float(), rng.next_float());
            const auto s = kept.sample(wo, u_lobe, u, Transport::Radiance);
            const auto s_ref = fresh3.sample(wo, u_lobe, u, Transport::Radiance);
            ASSERT_EQ(bool(s), bool(s_ref)) << what;
            if (!s) continue;
            ASSERT_EQ(s->pdf, s_ref->pdf) << what;
            ASSERT_EQ(s->f.x, s_ref->f.x) << what;
            if (s->is_specular()) continue;
            const MetalRoughBsdf fresh4(p), fresh5(p);
            const Spectrum fs = fresh4.eval(wo, s->wi, Transport::Radiance);
            ASSERT_EQ(s->f.x, fs.x) << what;
            ASSERT_EQ(s->f.y, fs.y) << what;
            ASSERT_EQ(s->f.z, fs.z) << what;
            ASSERT_EQ(s->pdf, fresh5.pdf(wo, s->wi, Transport::Radiance)) << what;
        }
    }
}

TEST(MetalRoughBsdf, Reciprocity) {
    Rng rng(8);
    for (int i = 0; i < 4000; ++i) {
        // Roughness 0 too: the diffuse base of a mirror must be reciprocal as well.
        const float roughness = i % 5 == 0 ? 0.0f : rng.next_float();
        const MetalRoughParams p = params(i, roughness, rng.next_float());
        const MetalRoughBsdf bsdf(p);
        const Vec3 wo = spherical_direction(0.02f + 0.98f * rng.next_float(), 6 * rng.next_float());
        const Vec3 wi = spherical_direction(0.02f + 0.98f * rng.next_float(), 6 * rng.next_float());
        expect_relative(bsdf.eval(wo, wi, Transport::Radiance),
                        bsdf.eval(wi, wo, Transport::Radiance), 1e-4f, describe(p, wo));
    }
}

// The specular albedo table's interpolation error (tests/materials/specular_albedo_test):
// the energy-conserving layering reflects 1 + (E_true - E_table)(wo) for a white base.
constexpr float kTableTolerance = 2e-3f;

// Directional albedo of a white material: at most 1 (3 sigma of the estimate, plus float
// rounding and the table's error), for every roughness and view angle, including
// grazing ones (cos 0.01).
void expect_white_furnace(float metallic, float extra_tolerance) {
    for (float roughness : {0.0f, 0.05f, 0.3f, 0.7f, 1.0f})
        for (float cos_o : {1.0f, 0.7f, 0.3f, 0.05f, 0.01f}) {
            MetalRoughParams p;
            p.base_color = Spectrum(1);
            p.alpha = roughness * roughness;
            p.metallic = metallic;
            const Vec3 wo = spherical_direction(cos_o, 1.3f);
            const test::AlbedoEstimate a =
                test::directional_albedo(MetalRoughBsdf(p), wo, 20000, 9);
            EXPECT_LE(a.mean.x, 1 + 3 * a.std_error.x + 1e-5f + extra_tolerance)
                << describe(p, wo) << ": albedo " << a.mean.x << " +- " << a.std_error.x;
        }
}

TEST(MetalRoughBsdf, WhiteFurnaceMetal) { expect_white_furnace(1.0f, 0); }
TEST(MetalRoughBsdf, WhiteFurnaceHalfMetal) { expect_white_furnace(0.5f, kTableTolerance); }
TEST(MetalRoughBsdf, WhiteFurnaceDielectric) { expect_white_furnace(0.0f, kTableTolerance); }

// With albedo scaling a white dielectric loses nothing: the specular lobe reflects
// E(wo) and the base exactly the rest. A wrong normalization (1 - E_avg) or a base
// weighted on one side only would show here at some angle and roughness.
TEST(MetalRoughBsdf, WhiteDielectricReflectsEverything) {
    for (float roughness : {0.0f, 0.05f, 0.3f, 0.7f, 1.0f})
        for (float cos_o : {1.0f, 0.7f, 0.3f, 0.05f, 0.01f}) {
            MetalRoughParams p;
            p.base_color = Spectrum(1);
            p.alpha = roughness * roughness;
            p.metallic = 0;
            const Vec3 wo = spherical_direction(cos_o, 0.4f);
            const test::AlbedoEstimate a =
                test::directional_albedo(MetalRoughBsdf(p), wo, 40000, 12);
            EXPECT_NEAR(a.mean.x, 1.0f, 3 * a.std_error.x + 1e-5f + kTableTolerance)
                << describe(p, wo) << ": albedo " << a.mean.x << " +- " << a.std_error.x;
        }
}

// KHR_materials_specular with specularFactor 0 leaves no layer: the base is exactly
// Lambertian in both layerings.
TEST(MetalRoughBsdf, NoSpecularLayerIsLambertian) {
    for (GltfLayering layering : {GltfLayering::AlbedoScaled, GltfLayering::Spec}) {
        MetalRoughParams p;
        p.base_color = {0.7f, 0.3f, 0.5f};
        p.metallic = 0;
        p.alpha = 0.3f;
        p.dielectric_f0 = Spectrum(0);
        p.dielectric_f90 = 0;
        p.layering = layering;
        const MetalRoughBsdf bsdf(p);
        Rng rng(13);
        for (int i = 0; i < 200; ++i) {
            const Vec3 wo = spherical_direction(0.01f + 0.99f * rng.next_float(), 6 * rng.next_float());
            const Vec3 wi = spherical_direction(0.01f + 0.99f * rng.next_float(), 6 * rng.next_float());
            expect_relative(bsdf.eval(wo, wi, Transport::Radiance), p.base_color * kInvPi, 1e-6f,
                            describe(p, wo));
            EXPECT_FLOAT_EQ(bsdf.pdf(wo, wi, Transport::Radiance), cosine_hemisphere_pdf(wi));
            // Sampling is cosine-weighted: the weight is the base colour, the direction
            // the cosine warp of u.
            const Vec2 u(rng.next_float(), rng.next_float());
            const auto s = bsdf.sample(wo, rng.next_float(), u, Transport::Radiance);
            ASSERT_TRUE(s);
            EXPECT_EQ(s->lobe, Lobe::Diffuse);
            const Vec3 expected = square_to_cosine_hemisphere(u);
            EXPECT_FLOAT_EQ(s->wi.z, expected.z);
            expect_relative(s->f * (s->wi.z / s->pdf), p.base_color, 1e-5f, describe(p, wo));
        }
    }
}

// The glTF 2.0 dielectric BRDF as Appendix B writes it (fresnel_mix, --gltf-layering
// spec) gains energy away from normal incidence: the diffuse base is weighted by
// 1 - F(v.h), and for light arriving near the normal v.h stays large while the specular
// lobe reflects F(n.v). A white dielectric reflects about 1.0006 at wo.z = 0.7, 1.15 at
// 0.3 and 1.7 at 0.05 (1.35 at metallic 0.5). This pins that behaviour of the optional
// spec layering: near-conserving close to the normal, a bounded grazing gain.
TEST(MetalRoughBsdf, WhiteFurnaceDielectricFollowsTheSpec) {
    for (float metallic : {0.0f, 0.5f})
        for (float roughness : {0.0f, 0.05f, 0.3f, 0.7f, 1.0f})
            for (float cos_o : kCosOs) {
                MetalRoughParams p;
                p.base_color = Spectrum(1);
                p.alpha = roughness * roughness;
                p.metallic = metallic;
                p.layering = GltfLayering::Spec;
                const Vec3 wo = spherical_direction(cos_o, 1.3f);
                const test::AlbedoEstimate a =
                    test::directional_albedo(MetalRoughBsdf(p), wo, 20000, 9);
                const float bound = cos_o >= 0.7f ? 1.002f : 1.8f;
                EXPECT_LE(a.mean.x, bound + 3 * a.std_error.x)
                    << describe(p, wo) << ": albedo " << a.mean.x << " +- " << a.std_error.x;
            }
}

TEST(MetalRoughBsdf, WhiteMirrorReflectsEverything) {
    MetalRoughParams p;
    p.base_color = Spectrum(1);
    p.metallic = 1;
    p.alpha = 0;
    const MetalRoughBsdf bsdf(p);
    Rng rng(10);
    for (float cos_o : kCosOs) {
        const Vec3 wo = spherical_direction(cos_o, 0.5f);
        for (int i = 0; i < 100; ++i) {
            const auto s = bsdf.sample(wo, rng.next_float(), {rng.next_float(), rng.next_float()},
                                       Transport::Radiance);
            ASSERT_TRUE(s);
            ASSERT_TRUE(s->is_specular());
            EXPECT_EQ(s->pdf, 1.0f);
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(s->weight()[c], 1.0f, 1e-6f);
        }
        EXPECT_TRUE(is_black(bsdf.eval(wo, Vec3(-wo.x, -wo.y, wo.z), Transport::Radiance)));
    }
}

// The wo terms a thread keeps (its last wo's, per model) belong to the model that made
// them, not to its address: a hit's model is built where the last hit's was, and may
// be asked about the same wo (an orthographic view of a textured plane). Model b, built
// in a's place and asked what a was asked, answers as a b built anywhere else.
TEST(MetalRoughBsdf, AModelBuiltWhereAnotherWasDoesNotReuseItsTerms) {
    const MetalRoughParams a = params(0, 0.5f, 0.0f), b = params(2, 0.3f, 0.5f);
    const Vec3 wo = spherical_direction(0.6f, 0.4f), wi = spherical_direction(0.8f, 2.5f);
    // Alive throughout, so that no model below is built where these are.
    const MetalRoughBsdf a_model(a), b_model(b);
    float b_pdf;
    const Spectrum a_ref = a_model.eval(wo, wi, Transport::Radiance);
    const Spectrum b_f = b_model.eval_pdf(wo, wi, Transport::Radiance, &b_pdf);
    std::optional<MetalRoughBsdf> slot;
    slot.emplace(a);
    const void* where = &*slot;
    float pdf;
    const Spectrum a_f = slot->eval_pdf(wo, wi, Transport::Radiance, &pdf);
    slot.emplace(b);
    ASSERT_EQ(static_cast<const void*>(&*slot), where);
    const Spectrum f = slot->eval_pdf(wo, wi, Transport::Radiance, &pdf);
    EXPECT_EQ(a_f.x, a_ref.x);
    EXPECT_NE(a_f.x, b_f.x);  // else the test could not tell
    EXPECT_EQ(f.x, b_f.x);
    EXPECT_EQ(f.y, b_f.y);
    EXPECT_EQ(f.z, b_f.z);
    EXPECT_EQ(pdf, b_pdf);
    // A copy holds the same parameters, so it may share its original's terms.
    const MetalRoughBsdf copy = *slot;
    float copy_pdf;
    const Spectrum copy_f = copy.eval_pdf(wo, wi, Transport::Radiance, &copy_pdf);
    EXPECT_EQ(copy_f.x, b_f.x);
    EXPECT_EQ(copy_pdf, b_pdf);
}

TEST(MetalRoughBsdf, NothingBelowTheHorizon) {
    for (float roughness : {0.0f, 0.5f}) {
        const MetalRoughBsdf bsdf(params(0, roughness, 0.5f));
        const Vec3 up = spherical_direction(0.5f, 1), down = spherical_direction(-0.5f, 2);
        EXPECT_TRUE(is_black(bsdf.eval(up, down, Transport::Radiance)));
        EXPECT_TRUE(is_black(bsdf.eval(down, up, Transport::Radiance)));
        EXPECT_EQ(bsdf.pdf(up, down, Transport::Radiance), 0.0f);
        EXPECT_EQ(bsdf.pdf(down, up, Transport::Radiance), 0.0f);
        EXPECT_FALSE(bsdf.sample(down, 0.5f, {0.3f, 0.6f}, Transport::Radiance));
        EXPECT_FALSE(bsdf.sample(down, 0.01f, {0.3f, 0.6f}, Transport::Radiance));
    }
}

}  // namespace
}  // namespace penumbra
