// The glTF material with KHR_materials_transmission: a mixture of the opaque glTF BRDF
// and a rough dielectric. Sampling against the pdf over the whole sphere (rough and
// smooth, where the dielectric's Dirac lobes leave the rest of the pdf integrating to
// the probability of the non-specular part), eval/pdf agreement, and the furnace; for
// the refracting boundary of a volume and for the thin-walled sheet.
#include "materials/gltf_transmission_bsdf.h"

#include <gtest/gtest.h>

#include <sstream>

#include "support/bsdf/bsdf_properties.h"

namespace penumbra {
namespace {

using test::spherical_direction;

GltfTransmissionBsdf make(float roughness, float metallic, float transmission, Spectrum base,
                          MicrofacetType type = MicrofacetType::Ggx, bool front = true,
                          bool thin = false) {
    MetalRoughParams p;
    p.base_color = base;
    p.metallic = metallic;
    p.alpha = roughness * roughness;
    p.distribution = type;
    DielectricParams d;
    d.eta = front ? 1.5f : 1 / 1.5f;
    d.alpha = p.alpha;
    d.distribution = type;
    d.transmittance = base;
    if (thin) d.eta = 1.5f;  // a sheet: the same medium on both sides
    return GltfTransmissionBsdf(p, transmission, d, thin);
}

std::string describe(float roughness, float metallic, float transmission, Vec3 wo) {
    std::ostringstream s;
    s << "roughness " << roughness << ", metallic " << metallic << ", transmission " << transmission
      << ", wo.z " << wo.z;
    return s.str();
}

TEST(GltfTransmissionBsdf, SamplesFollowThePdf) {
    struct Case {
        float roughness, metallic, transmission, cos_o;
        MicrofacetType type;
    };
    const Case cases[] = {
        {0.5f, 0.0f, 1.0f, 0.8f, MicrofacetType::Ggx},
        {0.5f, 0.3f, 0.6f, 0.05f, MicrofacetType::Ggx},
        {1.0f, 0.0f, 0.5f, 0.4f, MicrofacetType::Beckmann},
        {0.2f, 0.5f, 1.0f, 0.9f, MicrofacetType::Beckmann},
        {0.0f, 0.0f, 0.7f, 0.6f, MicrofacetType::Ggx},   // smooth glass over diffuse
        {0.0f, 0.4f, 0.5f, 0.05f, MicrofacetType::Ggx},  // and a mirror metal, grazing
    };
    test::BsdfChi2Options o;
    o.samples = 100000;
    o.significance = test::sidak_significance(0.01, std::size(cases));
    int seed = 600;
    for (const Case& c : cases) {
        const GltfTransmissionBsdf bsdf =
            make(c.roughness, c.metallic, c.transmission, {0.9f, 0.7f, 0.4f}, c.type);
        const Vec3 wo = spherical_direction(c.cos_o, 1.4f);
        o.seed = ++seed;
        const test::Chi2Result r = test::bsdf_chi2_sphere(bsdf, wo, o);
        const std::string what = describe(c.roughness, c.metallic, c.transmission, wo);
        EXPECT_TRUE(r.passed) << what << "\n" << r.report;
        // The pdf integrates to the probability of a non-specular sample (1 when rough,
        // less by the Dirac lobes' share when smooth).
        const double lost = double(r.lost) / r.samples;
        EXPECT_NEAR(r.pdf_integral, 1 - lost, 5 * std::sqrt(lost / r.samples) + 2e-4) << what;
    }
}

TEST(GltfTransmissionBsdf, SampleAgreesWithEvalAndPdf) {
    Rng rng(14);
    for (int i = 0; i < 200; ++i) {
        const float roughness = i % 7 == 0 ? 0.0f : rng.next_float();
        const float metallic = i % 3 == 0 ? 0.0f : rng.next_float();
        const GltfTransmissionBsdf bsdf =
            make(roughness, metallic, 0.2f + 0.8f * rng.next_float(), {0.8f, 0.5f, 0.3f},
                 i % 2 ? MicrofacetType::Beckmann : MicrofacetType::Ggx, i % 4 != 0);
        const Vec3 wo = test::random_direction(rng);
        EXPECT_EQ(test::check_sample_agreement(bsdf, wo, 40, i, Transport::Radiance), "")
            << describe(roughness, metallic, 0, wo);
        // Its reflection (opaque part and dielectric reflection) is reciprocal.
        if (i % 10 == 0) {
            EXPECT_EQ(test::check_reciprocity(bsdf, 100, i), "")
                << describe(roughness, metallic, 0, wo);
        }
    }
}

TEST(GltfTransmissionBsdf, WhiteFurnace) {
    // Light arriving from wo (importance) is never more than conserved, from the front
    // and from the back of the surface. Transmission 1 leaves no diffuse base (whose
    // spec form gains energy at grazing angles; see metal_rough_bsdf_test.cpp), so the
    // opaque part here is pure metal.
    for (float roughness : {0.0f, 0.3f, 1.0f})
        for (float metallic : {0.0f, 0.5f})
            for (float cos_o : {1.0f, 0.4f, 0.05f})
                for (bool front : {true, false}) {
                    const GltfTransmissionBsdf bsdf =
                        make(roughness, metallic, 1.0f, Spectrum(1), MicrofacetType::Ggx, front);
                    const Vec3 wo = spherical_direction(cos_o, 0.7f);
                    const test::AlbedoEstimate a =
                        test::directional_albedo(bsdf, wo, 20000, 15, Transport::Importance);
                    EXPECT_LE(a.mean.x, 1 + 3 * a.std_error.x + 1e-5f)
                        << describe(roughness, metallic, 1, wo) << (front ? "" : ", back") << ": "
                        << a.mean.x;
                }
    // Smooth, white, non-metal, fully transmissive: lossless glass.
    const test::AlbedoEstimate glass = test::directional_albedo(
        make(0, 0, 1, Spectrum(1)), spherical_direction(0.6f, 0), 10000, 16, Transport::Importance);
    EXPECT_NEAR(glass.mean.x, 1.0f, 1e-5f);
}

TEST(GltfTransmissionBsdf, ThinWalledSamplesFollowThePdfAndConserveEnergy) {
    // Without KHR_materials_volume the dielectric is a ThinDielectricBsdf sheet: the same
    // mixture, sampled against its pdf over the sphere, agreeing with eval, never
    // gaining energy, and lossless when smooth, white and fully transmissive.
    struct Case {
        float roughness, metallic, transmission, cos_o;
    };
    const Case cases[] = {{0.5f, 0.0f, 1.0f, 0.8f}, {0.3f, 0.3f, 0.6f, 0.05f},
                          {1.0f, 0.0f, 0.5f, -0.4f}, {0.0f, 0.2f, 0.7f, 0.6f}};
    test::BsdfChi2Options o;
    o.samples = 100000;
    o.significance = test::sidak_significance(0.01, std::size(cases));
    int seed = 700;
    for (const Case& c : cases) {
        const GltfTransmissionBsdf bsdf = make(c.roughness, c.metallic, c.transmission,
                                               {0.9f, 0.7f, 0.4f}, MicrofacetType::Ggx, true, true);
        const Vec3 wo = spherical_direction(c.cos_o, 1.4f);
        o.seed = ++seed;
        const test::Chi2Result r = test::bsdf_chi2_sphere(bsdf, wo, o);
        const std::string what = describe(c.roughness, c.metallic, c.transmission, wo) + ", thin";
        EXPECT_TRUE(r.passed) << what << "\n" << r.report;
        const double lost = double(r.lost) / r.samples;
        EXPECT_NEAR(r.pdf_integral, 1 - lost, 5 * std::sqrt(lost / r.samples) + 2e-4) << what;
        EXPECT_EQ(test::check_sample_agreement(bsdf, wo, 200, seed, Transport::Radiance), "")
            << what;
    }
    for (float roughness : {0.0f, 0.3f, 1.0f})
        for (float cos_o : {1.0f, 0.4f, 0.05f, -0.6f}) {
            const GltfTransmissionBsdf bsdf =
                make(roughness, 0.5f, 1.0f, Spectrum(1), MicrofacetType::Ggx, true, true);
            const Vec3 wo = spherical_direction(cos_o, 0.7f);
            const test::AlbedoEstimate a =
                test::directional_albedo(bsdf, wo, 20000, 15, Transport::Importance);
            EXPECT_LE(a.mean.x, 1 + 3 * a.std_error.x + 1e-5f)
                << describe(roughness, 0.5f, 1, wo) << ", thin: " << a.mean.x;
        }
    const test::AlbedoEstimate sheet =
        test::directional_albedo(make(0, 0, 1, Spectrum(1), MicrofacetType::Ggx, true, true),
                                 spherical_direction(0.6f, 0), 10000, 16, Transport::Radiance);
    EXPECT_NEAR(sheet.mean.x, 1.0f, 1e-5f);
}

TEST(GltfTransmissionBsdf, NoTransmissionIsTheOpaqueMaterial) {
    MetalRoughParams p;
    p.base_color = {0.7f, 0.2f, 0.4f};
    p.metallic = 0.3f;
    p.alpha = 0.2f;
    const MetalRoughBsdf opaque(p);
    const GltfTransmissionBsdf mixed(p, 0, DielectricParams{});
    Rng rng(17);
    for (int i = 0; i < 200; ++i) {
        const Vec3 wo = test::random_direction(rng), wi = test::random_direction(rng);
        EXPECT_EQ(mixed.eval(wo, wi, Transport::Radiance),
                  opaque.eval(wo, wi, Transport::Radiance));
        EXPECT_EQ(mixed.pdf(wo, wi, Transport::Radiance), opaque.pdf(wo, wi, Transport::Radiance));
    }
}

}  // namespace
}  // namespace penumbra
