#include "materials/bsdf_calls.h"

#include <gtest/gtest.h>

#include <cstring>

#include "core/lights/directional_light.h"
#include "core/lights/point_light.h"
#include "core/lights/spot_light.h"
#include "core/sampling/rng.h"
#include "materials/metal_rough_bsdf.h"
#include "materials/lobes/oren_nayar.h"
#include "support/bsdf/bsdf_checks.h"

namespace penumbra {
namespace {

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same_bits(Vec3 a, Vec3 b) {
    return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z);
}

// The direct calls give what the virtual ones give, bit for bit, on directions on both
// sides of the surface, for the Lambertian model they call directly and for others they
// pass on.
void expect_same_as_virtual(const Bsdf& bsdf) {
    Rng rng(17);
    for (int i = 0; i < 2000; ++i) {
        const Vec3 wo = test::spherical_direction(2 * rng.next_float() - 1, 6.28f * rng.next_float());
        const Vec3 wi = test::spherical_direction(2 * rng.next_float() - 1, 6.28f * rng.next_float());
        const Transport mode = i % 2 ? Transport::Radiance : Transport::Importance;
        EXPECT_TRUE(same_bits(bsdf_eval(bsdf, wo, wi, mode), bsdf.eval(wo, wi, mode)));
        float pdf_direct = -1, pdf_virtual = -2;
        const Spectrum f_direct = bsdf_eval_pdf(bsdf, wo, wi, mode, &pdf_direct);
        const Spectrum f_virtual = bsdf.eval_pdf(wo, wi, mode, &pdf_virtual);
        EXPECT_TRUE(same_bits(f_direct, f_virtual));
        EXPECT_TRUE(same_bits(pdf_direct, pdf_virtual));
        const float u_lobe = rng.next_float();
        const Vec2 u(rng.next_float(), rng.next_float());
        const std::optional<BsdfSample> a = bsdf_sample(bsdf, wo, u_lobe, u, mode);
        const std::optional<BsdfSample> b = bsdf.sample(wo, u_lobe, u, mode);
        ASSERT_EQ(a.has_value(), b.has_value());
        if (!a) continue;
        EXPECT_TRUE(same_bits(a->wi, b->wi));
        EXPECT_TRUE(same_bits(a->f, b->f));
        EXPECT_TRUE(same_bits(a->pdf, b->pdf));
        EXPECT_EQ(a->lobe, b->lobe);
    }
}

TEST(BsdfCalls, DirectCallsMatchTheVirtualOnes) {
    const LambertianBsdf lambert(Spectrum(0.2f, 0.5f, 0.8f));
    EXPECT_TRUE(lambert.is_lambertian());
    expect_same_as_virtual(lambert);
    const OrenNayarBsdf oren_nayar(Spectrum(0.6f), 0.4f);
    EXPECT_FALSE(oren_nayar.is_lambertian());
    expect_same_as_virtual(oren_nayar);
    MetalRoughParams p;
    p.base_color = Spectrum(0.9f, 0.6f, 0.3f);
    p.metallic = 0.3f;
    p.alpha = 0.16f;
    const MetalRoughBsdf metal_rough(p);
    EXPECT_FALSE(metal_rough.is_lambertian());
    expect_same_as_virtual(metal_rough);
}

// to_bsdf_local: the direct calls give every model the bits they give it in the full
// local frame, the Lambertian one (whose x and y are left 0) included, with a frame that
// is not the identity.
TEST(BsdfCalls, LocalDirectionsAsTheCallsReadThem) {
    const LambertianBsdf lambert(Spectrum(0.2f, 0.5f, 0.8f));
    MetalRoughParams p;
    p.base_color = Spectrum(0.9f, 0.6f, 0.3f);
    p.metallic = 0.3f;
    p.alpha = 0.16f;
    const MetalRoughBsdf metal_rough(p);
    const Frame frame = Frame::from_normal(normalize(Vec3(0.3f, -0.8f, 0.52f)));
    Rng rng(23);
    for (const Bsdf* bsdf :
         {static_cast<const Bsdf*>(&lambert), static_cast<const Bsdf*>(&metal_rough)}) {
        for (int i = 0; i < 2000; ++i) {
            const Vec3 wo_world =
                test::spherical_direction(2 * rng.next_float() - 1, 6.28f * rng.next_float());
            const Vec3 wi_world =
                test::spherical_direction(2 * rng.next_float() - 1, 6.28f * rng.next_float());
            const Vec3 wo = to_bsdf_local(*bsdf, frame, wo_world);
            const Vec3 wi = to_bsdf_local(*bsdf, frame, wi_world);
            const Vec3 wo_full = frame.to_local(wo_world), wi_full = frame.to_local(wi_world);
            EXPECT_TRUE(same_bits(wo.z, wo_full.z));
            float pdf = -1, pdf_full = -2;
            EXPECT_TRUE(
                same_bits(bsdf_eval_pdf(*bsdf, wo, wi, Transport::Radiance, &pdf),
                          bsdf_eval_pdf(*bsdf, wo_full, wi_full, Transport::Radiance, &pdf_full)));
            EXPECT_TRUE(same_bits(pdf, pdf_full));
            const Vec2 u(rng.next_float(), rng.next_float());
            const float u_lobe = rng.next_float();
            const std::optional<BsdfSample> a =
                bsdf_sample(*bsdf, wo, u_lobe, u, Transport::Radiance);
            const std::optional<BsdfSample> b =
                bsdf_sample(*bsdf, wo_full, u_lobe, u, Transport::Radiance);
            ASSERT_EQ(a.has_value(), b.has_value());
            if (a) {
                EXPECT_TRUE(same_bits(a->wi, b->wi));
                EXPECT_TRUE(same_bits(a->f, b->f));
                EXPECT_TRUE(same_bits(a->pdf, b->pdf));
            }
        }
    }
}

TEST(LightCalls, PointLightsAloneAreCalledDirectlyWithTheSameSample) {
    const PointLight point({0.3f, 0.9f, -0.2f}, Spectrum(2, 3, 4));
    EXPECT_TRUE(point.is_point());
    EXPECT_FALSE(SpotLight({0, 1, 0}, {0, -1, 0}, Spectrum(1), 0.2f, 0.5f).is_point());
    EXPECT_FALSE(DirectionalLight({0, -1, 0}, Spectrum(1), 10).is_point());
    Rng rng(3);
    for (int i = 0; i < 1000; ++i) {
        const ShadingPoint ref{{rng.next_float(), rng.next_float(), rng.next_float()}, {0, 1, 0}};
        const Vec2 u(rng.next_float(), rng.next_float());
        const std::optional<LightSample> a = sample_light_Li(point, ref, u, 0.5f);
        const std::optional<LightSample> b = static_cast<const Light&>(point).sample_Li(ref, u, 0.5f);
        ASSERT_TRUE(a && b);
        EXPECT_TRUE(same_bits(a->wi, b->wi));
        EXPECT_TRUE(same_bits(a->Li, b->Li));
        EXPECT_TRUE(same_bits(a->dist, b->dist));
        EXPECT_EQ(a->delta, b->delta);
    }
    // At the light itself there is no direction: no sample either way.
    EXPECT_FALSE(sample_light_Li(point, ShadingPoint{{0.3f, 0.9f, -0.2f}, {0, 1, 0}}, {}, 0));
}

}  // namespace
}  // namespace penumbra
