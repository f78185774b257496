// Lights that break naive estimators (scenes/hard/lights.gltf): a point light sealed in
// a closed box, a zero-area emitter, a zero-intensity spot light, a tiny (1e-4 m) emitter
// of 1e8 nits; and an environment map whose energy is all in one texel. Results must be
// finite, exactly zero where no light can arrive, and of bounded variance.
#include <gtest/gtest.h>

#include <cmath>

#include "core/camera/orthographic_camera.h"
#include "io/gltf/gltf_loader.h"
#include "support/paths.h"
#include "support/render_scene.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

// Instances in lights.gltf (node order) and its punctual lights.
enum { kFloor = 0, kBox = 1, kZeroArea = 2, kTiny = 3 };
enum { kBoxedLight = 0, kDarkSpot = 1 };

Scene lights_scene(std::initializer_list<int> instances, std::initializer_list<int> lights) {
    Scene scene = load_gltf(test::source_path("scenes/hard/lights.gltf"));
    std::vector<Instance> keep_inst;
    for (int i : instances) keep_inst.push_back(scene.instances[size_t(i)]);
    scene.instances = keep_inst;
    std::vector<std::unique_ptr<Light>> keep_lights;
    for (int i : lights) keep_lights.push_back(std::move(scene.lights[size_t(i)]));
    scene.lights = std::move(keep_lights);
    return scene;
}

const OrthographicCamera& top_camera() {
    static const OrthographicCamera camera(
        Transform::look_at({0, 3, 0}, {0, 0, 0}, {0, 0, -1}), 2, 2, 48, 48);
    return camera;
}

struct Summary {
    float max = 0;
    double mean = 0;
    bool finite = true;
};

Summary summarize(const Image& img) {
    Summary s;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const float v = test::pixel_mean(img, x, y);
            if (!std::isfinite(v)) s.finite = false;
            s.max = std::max(s.max, v);
            s.mean += v / (img.width * img.height);
        }
    return s;
}

// Every integrator renders the scene exactly black, with no non-finite sample.
void expect_black(const Scene& scene) {
    for (const char* integrator : {"basic", "path", "direct"}) {
        const test::SceneRender r = test::render_scene(scene, top_camera(), integrator, 8);
        const Summary s = summarize(r.image);
        EXPECT_EQ(r.nonfinite_samples, 0u) << integrator;
        EXPECT_TRUE(s.finite) << integrator;
        EXPECT_EQ(s.max, 0.0f) << integrator;
    }
}

TEST(HardLights, LightSealedInABoxLightsNothing) {
    expect_black(lights_scene({kFloor, kBox}, {kBoxedLight}));
}

TEST(HardLights, ZeroAreaEmitterAndZeroIntensitySpotGiveBlackNotNaN) {
    expect_black(lights_scene({kFloor, kZeroArea}, {kDarkSpot}));
}

TEST(HardLights, TinyBrightEmitterGivesFirefliesNotNaNs) {
    const Scene scene = lights_scene({kFloor, kBox, kZeroArea, kTiny}, {kBoxedLight, kDarkSpot});
    const test::SceneRender r = test::render_scene(scene, top_camera(), "path", 16);
    const Summary s = summarize(r.image);
    EXPECT_EQ(r.nonfinite_samples, 0u);
    EXPECT_TRUE(s.finite);
    // The emitter (area 5e-9 m^2, 1e8 nits, 0.6 m above a floor of albedo 0.8 at y = -0.5)
    // gives the floor just below it E = L A / d^2 = 0.41 lux: radiance 0.8 / pi * 0.41 =
    // 0.10. Light sampling finds it, so the mean is of that order, not 0 or huge.
    EXPECT_GT(s.mean, 1e-3);
    EXPECT_LT(s.mean, 1.0);
    std::printf("tiny bright emitter: mean %.4g, brightest pixel %.4g\n", s.mean, s.max);
}

// A white floor under an environment that is black but for one texel of 1e4: the
// irradiance is that texel's radiance times its projected solid angle. Importance
// sampling puts nearly every light sample in the texel, so 16 samples per pixel land
// within a few percent everywhere (uniform sampling would hit it 1 time in 300).
TEST(HardLights, EnvironmentWithOneHotTexelKeepsVarianceBounded) {
    Scene scene;
    const int white = test::add_lambertian(scene, Spectrum(0.8f));
    const uint32_t floor = test::add_quad_object(scene, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2},
                                                 {-2, 0, -2}, white);
    test::add_instance(scene, floor, Transform());
    const int w = 64, h = 32, hot_x = 20, hot_y = 9;
    Image env(w, h, 3);
    const float L = 1e4f;
    for (int c = 0; c < 3; ++c) env.at(hot_x, hot_y)[c] = L;
    // E = L * dphi * integral of cos(theta) sin(theta) dtheta over the texel's rows.
    const float t0 = kPi * hot_y / h, t1 = kPi * (hot_y + 1) / h;
    const float E = L * (2 * kPi / w) * 0.5f * (std::sin(t1) * std::sin(t1) -
                                               std::sin(t0) * std::sin(t0));
    const float expected = 0.8f / kPi * E;

    const OrthographicCamera camera(Transform::look_at({0, 1, 0}, {0, 0, 0}, {0, 0, -1}), 1, 1,
                                    32, 32);
    const test::SceneRender r = test::render_scene(
        scene, camera, "path", 16, 3, 5,
        std::make_unique<EnvironmentLight>(std::move(env), 1.0f, 0.0f, 10.0f));
    EXPECT_EQ(r.nonfinite_samples, 0u);
    float worst = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x)
            worst = std::max(worst, std::abs(test::pixel_mean(r.image, x, y) / expected - 1));
    EXPECT_LT(worst, 0.1f);
    std::printf("hot environment texel: worst pixel off by %.4f of the expected %.4f\n", worst,
                expected);
}

}  // namespace
}  // namespace penumbra
