// KHR_materials_diffuse_transmission: the Lambertian transmission lobe and the glTF
// material that splits its diffuse base with it. Full-sphere chi-square, eval/pdf
// agreement, reciprocity of the lobe across the surface, the white furnace (a white
// material with white transmission colour reflects plus transmits exactly 1 at any
// factor), and factor 0 matching the models without it.
#include "materials/gltf_diffuse_transmission_bsdf.h"

#include <gtest/gtest.h>

#include <sstream>

#include "materials/gltf_transmission_bsdf.h"
#include "support/bsdf/bsdf_properties.h"

namespace penumbra {
namespace {

using test::spherical_direction;

struct Case {
    float roughness, metallic, factor, transmission;
};

std::string describe(const Case& c, Vec3 wo) {
    std::ostringstream s;
    s << "roughness " << c.roughness << ", metallic " << c.metallic << ", dt " << c.factor
      << ", transmission " << c.transmission << ", wo.z " << wo.z;
    return s.str();
}

MetalRoughParams params(const Case& c, Spectrum base) {
    MetalRoughParams p;
    p.base_color = base;
    p.metallic = c.metallic;
    p.alpha = c.roughness * c.roughness;
    return p;
}

DielectricParams glass(const Case& c, Spectrum base) {
    DielectricParams d;
    d.alpha = c.roughness * c.roughness;
    d.transmittance = base;
    return d;
}

GltfDiffuseTransmissionBsdf make(const Case& c, Spectrum base = {0.8f, 0.5f, 0.3f},
                                 Spectrum color = {0.9f, 0.3f, 0.6f}) {
    DiffuseTransmissionParams dt;
    dt.factor = c.factor;
    dt.color = color;
    return GltfDiffuseTransmissionBsdf(params(c, base), dt, c.transmission, glass(c, base));
}

TEST(GltfDiffuseTransmissionBsdf, SamplesFollowThePdf) {
    const Case cases[] = {
        {0.5f, 0.0f, 1.0f, 0.0f}, {0.5f, 0.0f, 0.5f, 0.0f}, {1.0f, 0.4f, 0.3f, 0.0f},
        {0.0f, 0.0f, 0.6f, 0.0f},  // smooth specular layer over the split base
        {0.3f, 0.2f, 0.5f, 0.5f},  // with KHR_materials_transmission
        {0.0f, 0.0f, 1.0f, 0.4f},
    };
    const float cos_os[] = {0.8f, 0.05f};
    test::BsdfChi2Options o;
    o.samples = 100000;
    o.significance = test::sidak_significance(0.01, std::size(cases) * std::size(cos_os));
    int seed = 300;
    for (const Case& c : cases)
        for (float cos_o : cos_os) {
            const Vec3 wo = spherical_direction(cos_o, 0.6f);
            o.seed = ++seed;
            const test::Chi2Result r = test::bsdf_chi2_sphere(make(c), wo, o);
            EXPECT_TRUE(r.passed) << describe(c, wo) << "\n" << r.report;
            const double lost = double(r.lost) / r.samples;
            EXPECT_NEAR(r.pdf_integral, 1 - lost, 5 * std::sqrt(lost / r.samples) + 1e-3)
                << describe(c, wo);
        }
}

TEST(GltfDiffuseTransmissionBsdf, SampleAgreesWithEvalAndPdf) {
    Rng rng(301);
    for (int i = 0; i < 200; ++i) {
        const Case c{i % 5 == 0 ? 0.0f : rng.next_float(), i % 3 == 0 ? 0.0f : rng.next_float(),
                     rng.next_float(), i % 4 == 0 ? rng.next_float() : 0.0f};
        const Vec3 wo = test::random_direction(rng, 0.01f);
        EXPECT_EQ(test::check_sample_agreement(make(c), wo, 40, i, Transport::Radiance), "")
            << describe(c, wo);
    }
}

TEST(GltfDiffuseTransmissionBsdf, LobeIsReciprocalAcrossTheSurface) {
    // f(wo, wi) = f(wi, wo) with wo and wi on opposite sides, both layerings.
    Rng rng(302);
    for (int i = 0; i < 1000; ++i) {
        MetalRoughParams p = params({i % 4 == 0 ? 0.0f : rng.next_float(), 0, 1, 0}, Spectrum(1));
        p.layering = i % 2 ? GltfLayering::Spec : GltfLayering::AlbedoScaled;
        const DiffuseTransmissionLobe lobe({0.7f, 0.4f, 0.2f}, SpecularLayerTransmittance(p));
        const Vec3 wo = test::random_direction(rng, 0.01f);
        const Vec3 wi = test::random_direction(rng, 0.01f, true);
        const Spectrum a = lobe.eval(wo, wi), b = lobe.eval(wi, wo);
        EXPECT_GT(a.x, 0.0f);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], 1e-5f * a[k]);
        EXPECT_EQ(lobe.eval(wo, Vec3(wi.x, wi.y, -wi.z)), Spectrum(0));  // no reflection
    }
}

TEST(GltfDiffuseTransmissionBsdf, WhiteFurnaceIsExactForAnySplit) {
    // A white dielectric reflects E(wo) + (1 - E(wo)) = 1 (metal_rough_bsdf.h); moving a
    // share dt of its base to white transmission changes where light goes, not how much.
    // Tolerance: the specular albedo table's interpolation error, as there.
    constexpr float kTableTolerance = 2e-3f;
    int seed = 310;
    for (float roughness : {0.0f, 0.3f, 1.0f})
        for (float factor : {0.0f, 0.5f, 1.0f})
            for (float cos_o : {1.0f, 0.4f, 0.01f}) {
                const Case c{roughness, 0, factor, 0};
                const Vec3 wo = spherical_direction(cos_o, 1.7f);
                const test::AlbedoEstimate a =
                    test::directional_albedo(make(c, Spectrum(1), Spectrum(1)), wo, 20000, ++seed);
                EXPECT_NEAR(a.mean.x, 1.0f, 4 * a.std_error.x + kTableTolerance) << describe(c, wo);
            }
    // Coloured: never a gain.
    for (float cos_o : {1.0f, 0.05f}) {
        const Case c{0.5f, 0.3f, 0.7f, 0.2f};
        const Vec3 wo = spherical_direction(cos_o, 1.7f);
        const test::AlbedoEstimate a =
            test::directional_albedo(make(c, Spectrum(1), Spectrum(1)), wo, 20000, ++seed);
        EXPECT_LE(a.mean.x, 1 + 3 * a.std_error.x + kTableTolerance) << describe(c, wo);
    }
}

TEST(GltfDiffuseTransmissionBsdf, FactorZeroIsTheModelWithout) {
    // With dt = 0 the mixture's value is the metal-roughness (or transmission) model's,
    // to float rounding (their metallic blends are written differently).
    Rng rng(320);
    for (int i = 0; i < 300; ++i) {
        const Case c{0.05f + 0.95f * rng.next_float(), rng.next_float(), 0,
                     i % 2 ? rng.next_float() : 0.0f};
        const Spectrum base(0.7f, 0.4f, 0.2f);
        const GltfDiffuseTransmissionBsdf mixed = make(c, base);
        const GltfTransmissionBsdf reference(params(c, base), c.transmission, glass(c, base));
        const Vec3 wo = test::random_direction(rng, 0.01f);
        const Vec3 wi = test::random_direction(rng, 0.01f, i % 3 == 0);
        const Spectrum a = mixed.eval(wo, wi, Transport::Radiance);
        const Spectrum b = reference.eval(wo, wi, Transport::Radiance);
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(a[k], b[k], 1e-5f * std::max(b[k], 1e-3f)) << describe(c, wo);
    }
}

}  // namespace
}  // namespace penumbra
