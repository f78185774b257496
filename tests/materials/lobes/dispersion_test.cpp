// KHR_materials_dispersion's IOR per channel: the spec's Cauchy fit at the C, d and F
// lines (red to blue spans the Abbe spread, green keeps the IOR), no change at
// dispersion 0 or without a channel, and Snell's law per channel through shade().
#include "materials/lobes/dispersion.h"

#include <gtest/gtest.h>

#include "materials/lobes/fresnel.h"
#include "materials/material.h"

namespace penumbra {
namespace {

TEST(Dispersion, IorPerChannelFollowsTheAbbeNumber) {
    for (float ior : {1.33f, 1.5f, 2.4f})
        for (float dispersion : {0.33f, 1.0f, 2.04f}) {
            const float abbe = 20 / dispersion;
            const float r = dispersion_ior(ior, dispersion, 0);
            const float g = dispersion_ior(ior, dispersion, 1);
            const float b = dispersion_ior(ior, dispersion, 2);
            // V_d = (n_d - 1) / (n_F - n_C).
            EXPECT_NEAR(b - r, (ior - 1) / abbe, 1e-4f * (ior - 1) / abbe + 1e-6f);
            // Green sits within 1e-4 of the spread of n_d (587.56 nm rounds the fit's 1.5168).
            EXPECT_NEAR(g, ior, 1e-4f * (ior - 1) / abbe + 1e-6f);
            EXPECT_LT(r, g);
            EXPECT_LT(g, b);
        }
    // Off: the IOR itself, bit for bit.
    EXPECT_EQ(dispersion_ior(1.5f, 0, 2), 1.5f);
    EXPECT_EQ(dispersion_ior(1.5f, 1, -1), 1.5f);
    // Never below 1 (the spec's max), even for absurd dispersion.
    EXPECT_EQ(dispersion_ior(1.05f, 200, 0), 1.0f);
}

TEST(Dispersion, EachChannelRefractsBySnellAtItsIor) {
    MaterialDesc m;
    m.base_color = {1, 1, 1, 1};
    m.metallic = 0;
    m.roughness = 0;
    m.ior = 1.6f;
    m.transmission = 1;
    m.thickness = 1;
    m.dispersion = 1.5f;
    Scene scene;
    scene.materials.push_back(m);
    SurfacePoint sp;
    sp.ng = sp.ns = Vec3(0, 0, 1);
    sp.dpdu = Vec3(1, 0, 0);
    sp.material = 0;
    const Vec3 wo_world = normalize(Vec3(0.8f, 0.0f, 0.6f));
    float sin_t[3];
    for (int c = 0; c < 3; ++c) {
        const ShadingData sd = shade(scene, sp, wo_world, {}, PathVolume{c, 0});
        const Vec3 wo = sd.frame.to_local(wo_world);
        const float eta = dispersion_ior(1.6f, 1.5f, c);
        const auto s = sd.bsdf.get()->sample(wo, 0.999f, {0.5f, 0.5f}, Transport::Radiance);
        ASSERT_TRUE(s);
        ASSERT_LT(s->wi.z, 0.0f);
        EXPECT_EQ(s->eta, eta);
        sin_t[c] = std::sqrt(1 - s->wi.z * s->wi.z);
        EXPECT_NEAR(std::sqrt(1 - wo.z * wo.z), eta * sin_t[c], 1e-5f) << "channel " << c;
    }
    // Blue bends most: the three directions differ by more than float noise.
    EXPECT_GT(sin_t[0] - sin_t[1], 1e-3f);
    EXPECT_GT(sin_t[1] - sin_t[2], 1e-3f);
    // Thin-walled (no volume): dispersion has no effect (it needs a volume).
    m.thickness = 0;
    scene.materials[0] = m;
    const ShadingData a = shade(scene, sp, wo_world, {}, PathVolume{0, 0});
    const ShadingData b = shade(scene, sp, wo_world, {});
    const Vec3 wo = a.frame.to_local(wo_world);
    EXPECT_EQ(a.bsdf.get()->sample(wo, 0.01f, {0.5f, 0.5f}, Transport::Radiance)->weight(),
              b.bsdf.get()->sample(wo, 0.01f, {0.5f, 0.5f}, Transport::Radiance)->weight());
}

}  // namespace
}  // namespace penumbra
