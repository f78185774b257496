// The bump terminator (scenes/hard/bump-plane.gltf: a plane whose normal map tilts every
// normal 40 degrees towards the sun's azimuth). Without Conty Estevez et al.'s shadowing
// the plane stays at 0.64 of its lit value as the sun sinks to the horizon and then
// drops to black at once; with it the light fades smoothly to 0 at grazing.
#include "integrators/direct_lighting.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/camera/orthographic_camera.h"
#include "core/lights/directional_light.h"
#include "io/gltf/gltf_loader.h"
#include "support/paths.h"
#include "support/render_scene.h"

namespace penumbra {
namespace {

TEST(BumpShadowing, IsOneWithoutANormalMapAndAtMostOneWithIt) {
    const Vec3 n = normalize(Vec3(0.1f, 1, -0.2f));
    for (int i = 0; i < 100; ++i) {
        const float e = (i + 0.5f) / 100 * kPi / 2;
        const Vec3 wi(std::cos(e), std::sin(e), 0.3f * std::cos(e));
        EXPECT_EQ(bump_shadowing(n, n, normalize(wi)), 1.0f);
        const float g = bump_shadowing({0, 1, 0}, normalize(Vec3(0.5f, 1, 0)), normalize(wi));
        EXPECT_GE(g, 0.0f);
        EXPECT_LE(g, 1.0f);
    }
}

// Radiance of the plane's centre with the sun `deg` above the horizon, in the tilt's
// azimuth (+x).
float plane_radiance(float deg) {
    Scene scene = load_gltf(test::source_path("scenes/hard/bump-plane.gltf"));
    const float e = deg * kPi / 180;
    scene.lights.clear();
    scene.lights.push_back(std::make_unique<DirectionalLight>(
        -Vec3(std::cos(e), std::sin(e), 0), Spectrum(1), 10.0f));
    const OrthographicCamera camera(Transform::look_at({0, 1, 0}, {0, 0, 0}, {0, 0, -1}), 0.1f,
                                    0.1f, 4, 4);
    const test::SceneRender r = test::render_scene(scene, camera, "basic", 1);
    return test::pixel_mean(r.image, 2, 2);
}

TEST(BumpTerminator, LightFadesSmoothlyToTheHorizon) {
    const float tilt = 40 * kPi / 180, lit = 0.8f / kPi;
    float prev = 0;
    for (const float deg : {0.25f, 0.5f, 1.0f, 2.0f, 5.0f, 10.0f, 30.0f, 60.0f}) {
        const float e = deg * kPi / 180;
        // The mapped normal is (sin 40, cos 40, 0) up to 8-bit quantization of the texel.
        const float cos_b = std::sin(tilt + e);
        const float g = std::min(1.0f, std::sin(e) / (cos_b * std::cos(tilt)));
        const float expected = lit * cos_b * g * (1 + g - g * g);
        const float L = plane_radiance(deg);
        EXPECT_NEAR(L, expected, 0.02f * lit) << deg << " degrees";
        EXPECT_GT(L, prev) << deg << " degrees";  // monotone as the sun rises
        prev = L;
        if (deg <= 0.5f) EXPECT_LT(L, 0.03f * lit) << deg << " degrees";
    }
}

}  // namespace
}  // namespace penumbra
