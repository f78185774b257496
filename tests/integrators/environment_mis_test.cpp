// MIS compensation of environment maps (EnvironmentSampling::MisCompensated): a light
// sample never goes to a texel dimmer than the map's mean, so only the BSDF samples find
// those. The render must stay unbiased (every integrator that gets the compensated
// distribution pairs each light sample with a BSDF sample) and, on a sky-like map, be
// less noisy at equal samples, which is what it is for.
#include <gtest/gtest.h>

#include <cmath>

#include "core/camera/orthographic_camera.h"
#include "integrators/integrator.h"
#include "support/render_scene.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

// A sky as the efficiency harness's (scripts/crosscheck/efficiency_scenes.py): a blue
// gradient above the horizon, brown ground below and a small sun of radiance 100.
Image sky_with_sun(int w, int h) {
    Image img(w, h, 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = img.at(x, y);
            const float theta = kPi * (y + 0.5f) / h;
            if (theta < kPi / 2) {
                const float t = std::cos(theta);  // sin(elevation)
                p[0] = 0.6f * (0.4f + 0.6f * t);
                p[1] = 0.75f * (0.4f + 0.6f * t);
                p[2] = 0.4f + 0.6f * t;
            } else {
                p[0] = 0.12f, p[1] = 0.1f, p[2] = 0.08f;
            }
        }
    for (int y = 10; y < 12; ++y)
        for (int x = 40; x < 42; ++x)
            for (int c = 0; c < 3; ++c) img.at(x, y)[c] = 100;
    return img;
}

// The irradiance on an upward-facing plane, averaged over R, G, B: each texel of the upper
// half times its projected solid angle, dphi * (sin^2 theta1 - sin^2 theta0) / 2.
double upper_irradiance(const Image& img) {
    double e = 0;
    const double dphi = 2 * kPi / img.width;
    for (int y = 0; y < img.height / 2; ++y) {
        const double t0 = kPi * y / img.height, t1 = kPi * (y + 1) / img.height;
        const double proj = dphi * 0.5 * (std::sin(t1) * std::sin(t1) - std::sin(t0) * std::sin(t0));
        for (int x = 0; x < img.width; ++x) {
            const float* p = img.at(x, y);
            e += proj * (p[0] + p[1] + p[2]) / 3;
        }
    }
    return e;
}

struct FloorStats {
    double mean = 0;      // of the pixels, over the expected radiance
    double variance = 0;  // of the pixels (each an independent estimate of the same value)
};

// A Lambertian floor of albedo 0.8 seen from above: every pixel's expected radiance is
// 0.8 / pi times the upper hemisphere's irradiance (the floor hides the ground half).
FloorStats render_floor(const std::string& integrator, EnvironmentSampling sampling, uint32_t spp) {
    Scene scene;
    const int white = test::add_lambertian(scene, Spectrum(0.8f));
    const uint32_t floor = test::add_quad_object(scene, {-4, 0, 4}, {4, 0, 4}, {4, 0, -4},
                                                 {-4, 0, -4}, white);
    test::add_instance(scene, floor, Transform());
    const Image sky = sky_with_sun(128, 64);
    const double expected = 0.8 / kPi * upper_irradiance(sky);
    auto env = std::make_unique<EnvironmentLight>(sky, 1.0f, 0.0f, 10.0f, sampling);
    EXPECT_EQ(env->sampling(), sampling);
    const int n = 32;
    const OrthographicCamera camera(Transform::look_at({0, 1, 0}, {0, 0, 0}, {0, 0, -1}), 1, 1,
                                    n, n);
    const test::SceneRender r =
        test::render_scene(scene, camera, integrator, spp, 7, 5, std::move(env));
    EXPECT_EQ(r.nonfinite_samples, 0u);
    FloorStats s;
    double sum = 0, sum2 = 0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double v = test::pixel_mean(r.image, x, y) / expected;
            sum += v;
            sum2 += v * v;
        }
    s.mean = sum / (n * n);
    s.variance = sum2 / (n * n) - s.mean * s.mean;
    return s;
}

// 1024 pixels of 64 samples: the mean's standard error is about 0.1% here (the printed
// spread over sqrt(1024)), so a 1% tolerance is ten of them, and dropping the texels
// below the mean without the BSDF samples' weight would lose about 70% of the light.
TEST(EnvironmentMis, CompensatedPathTracingIsUnbiasedAndLessNoisy) {
    const FloorStats full = render_floor("path", EnvironmentSampling::Full, 64);
    const FloorStats comp = render_floor("path", EnvironmentSampling::MisCompensated, 64);
    std::printf("floor under a sky, path: mean full %.4f compensated %.4f; pixel variance "
                "compensated / full %.3f\n",
                full.mean, comp.mean, comp.variance / full.variance);
    EXPECT_NEAR(full.mean, 1.0, 0.01);
    EXPECT_NEAR(comp.mean, 1.0, 0.01);
    EXPECT_LT(comp.variance, 0.9 * full.variance);
}

TEST(EnvironmentMis, CompensatedDirectLightingIsUnbiased) {
    const FloorStats comp = render_floor("direct", EnvironmentSampling::MisCompensated, 64);
    std::printf("floor under a sky, direct: mean compensated %.4f\n", comp.mean);
    EXPECT_NEAR(comp.mean, 1.0, 0.01);
}

// Only integrators whose every light sample meets a BSDF sample under MIS may use it.
TEST(EnvironmentMis, OnlyIntegratorsThatPairLightAndBsdfSamplesAskForIt) {
    IntegratorOptions o;
    EXPECT_TRUE(make_integrator(IntegratorType::Path, o)->pairs_light_and_bsdf_samples());
    EXPECT_TRUE(make_integrator(IntegratorType::Direct, o)->pairs_light_and_bsdf_samples());
    EXPECT_FALSE(make_integrator(IntegratorType::Basic, o)->pairs_light_and_bsdf_samples());
    EXPECT_FALSE(make_integrator(IntegratorType::Albedo, o)->pairs_light_and_bsdf_samples());
    for (LightStrategy strategy : {LightStrategy::LightOnly, LightStrategy::BsdfOnly}) {
        IntegratorOptions one = o;
        one.strategy = strategy;
        EXPECT_FALSE(make_integrator(IntegratorType::Path, one)->pairs_light_and_bsdf_samples());
    }
    IntegratorOptions lights_only = o, bsdf_only = o;
    lights_only.bsdf_samples = 0;
    bsdf_only.light_samples = 0;
    EXPECT_FALSE(make_integrator(IntegratorType::Direct, lights_only)->pairs_light_and_bsdf_samples());
    EXPECT_FALSE(make_integrator(IntegratorType::Direct, bsdf_only)->pairs_light_and_bsdf_samples());
}

}  // namespace
}  // namespace penumbra
