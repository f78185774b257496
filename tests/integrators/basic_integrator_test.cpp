#include "integrators/basic_integrator.h"

#include <gtest/gtest.h>

#include "core/accel/embree_accel.h"
#include "io/gltf/gltf_loader.h"
#include "support/paths.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

Spectrum trace(const Scene& scene, const Accel& accel, Vec3 o, Vec3 d, int max_depth = 5) {
    IntegratorOptions opt;
    opt.max_depth = max_depth;
    BasicIntegrator integrator(opt);
    IndependentSampler sampler(1, 0);
    sampler.start_pixel_sample({0, 0}, 0);
    Ray r;
    r.o = o;
    r.d = normalize(d);
    const LightSet lights(scene, nullptr);
    return integrator.Li(r, RenderContext{scene, accel, lights}, sampler);
}

TEST(BasicIntegrator, CornellBoxFloorBelowTheLightMatchesAnalyticValue) {
    const Scene scene = load_gltf(test::source_path("scenes/cornell-box-point.gltf"));
    EmbreeAccel accel(scene);
    // Floor (0, -1, 0), white Lambertian 0.75, point light 8 cd at (0, 0.95, 0): see
    // scenes/README.md.
    // Looking straight down from inside the room (the camera's view of this point is
    // blocked by the short block).
    const Spectrum L = trace(scene, accel, {0, 0.5f, 0}, {0, -1, 0});
    const float expected = 0.75f / kPi * 8.0f / (1.95f * 1.95f);
    EXPECT_NEAR(L.x, expected, 1e-4f);
    EXPECT_NEAR(L.y, expected, 1e-4f);
    EXPECT_NEAR(L.z, expected, 1e-4f);
}

TEST(BasicIntegrator, RedWallReflectsOnlyRed) {
    const Scene scene = load_gltf(test::source_path("scenes/cornell-box-point.gltf"));
    EmbreeAccel accel(scene);
    // A point on the red wall (x = -1) at height 0.5, seen from the camera.
    const Vec3 p(-1, 0.5f, 0.6f), light(0, 0.95f, 0);
    const Spectrum L = trace(scene, accel, {0, 0, 3.9f}, p - Vec3(0, 0, 3.9f));
    const Vec3 to_light = light - p;
    const float d2 = length_squared(to_light);
    const float cos_theta = to_light.x / std::sqrt(d2);
    const Spectrum expected = Spectrum(0.63f, 0.065f, 0.05f) / kPi * 8.0f / d2 * cos_theta;
    EXPECT_NEAR(L.x, expected.x, 1e-4f);
    EXPECT_NEAR(L.y, expected.y, 1e-4f);
    EXPECT_NEAR(L.z, expected.z, 1e-4f);
}

TEST(BasicIntegrator, MirrorRecursionStopsAtMaxDepth) {
    // Two parallel mirrors facing each other, lit by a point light between them.
    Scene scene;
    MaterialDesc mirror;
    mirror.base_color = {1, 1, 1, 1};
    mirror.metallic = 1;
    mirror.roughness = 0;
    scene.materials.push_back(mirror);
    const uint32_t a = test::add_quad_object(scene, {-5, -5, -1}, {5, -5, -1}, {5, 5, -1},
                                             {-5, 5, -1}, 0);
    test::add_instance(scene, a, Transform());
    test::add_instance(scene, a, Transform::scale({1, 1, -1}));
    EmbreeAccel accel(scene);
    // A white metal mirror reflects everything, and nothing is lit directly (mirrors
    // have no diffuse part): the result is 0 whatever the depth, and must be finite.
    const Spectrum L = trace(scene, accel, {0, 0, 0}, {0.01f, 0, -1}, 50);
    EXPECT_TRUE(is_finite(L));
    EXPECT_EQ(L.x, 0.0f);
    // Each bounce is one closest-hit ray: max_depth bounds the ray count.
    const uint64_t before = accel.rays_traced();
    trace(scene, accel, {0, 0, 0}, {0.01f, 0, -1}, 7);
    EXPECT_EQ(accel.rays_traced() - before, 7u);
}

}  // namespace
}  // namespace penumbra
