// The denoiser's guides: through a mirror they describe what the mirror shows (its
// albedo tinted by the mirror's reflectance, its normal, the whole path's length); a
// rough surface or a diffuse one is the guide itself; an escaped ray leaves zeros.
#include "integrators/denoise_guide.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/accel/embree_accel.h"
#include "materials/lobes/fresnel.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

const Spectrum kWall(0.2f, 0.5f, 0.8f), kTint(0.9f, 0.6f, 0.3f);

// A camera at the origin looks down -z at a metal square at z = -2 turned 45 degrees
// about y, which shows a wall at x = 2 (the ray reflects to +x and meets it at distance
// 2 + 2). `roughness` is the metal's.
Scene mirror_scene(float roughness, bool with_wall = true) {
    Scene scene;
    MaterialDesc metal;
    metal.base_color = Vec4(kTint, 1);
    metal.metallic = 1;
    metal.roughness = roughness;
    metal.double_sided = true;
    scene.materials.push_back(metal);
    const Vec3 c(0, 0, -2), u = normalize(Vec3(1, 0, -1)) * 0.5f, v(0, 0.5f, 0);
    test::add_instance(scene,
                       test::add_quad_object(scene, c - u - v, c + u - v, c + u + v, c - u + v, 0),
                       Transform());
    if (!with_wall) return scene;
    const int wall = test::add_lambertian(scene, kWall);
    scene.materials[size_t(wall)].double_sided = true;
    test::add_instance(
        scene, test::add_quad_object(scene, {2, -2, 0}, {2, -2, -4}, {2, 2, -4}, {2, 2, 0}, wall),
        Transform());
    return scene;
}

Ray ray_along(Vec3 d) {
    Ray r;
    r.o = Vec3(0, 0, 0);
    r.d = d;
    return r;
}

void expect_near(Vec3 a, Vec3 b, float tol, const char* what) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], tol) << what << "[" << c << "]";
}

TEST(DenoiseGuide, GoesThroughAMirrorToWhatItShows) {
    const Scene scene = mirror_scene(0);
    EmbreeAccel accel(scene);
    const LightSet lights(scene, nullptr);
    const RenderContext ctx{scene, accel, lights};
    // The metal's Schlick reflectance at 45 degrees tints the wall's albedo.
    const Spectrum f = fresnel_schlick(kTint, 1, std::sqrt(0.5f));
    for (uint64_t key : {1u, 2u, 3u}) {
        const GuideRecord g = denoise_guide(ray_along({0, 0, -1}), ctx, key);
        expect_near(g.albedo, f * kWall, 1e-5f, "albedo");
        expect_near(g.normal, {-1, 0, 0}, 1e-5f, "normal");  // facing the reflected ray
        EXPECT_NEAR(g.depth, 4.0f, 1e-4f);
    }
}

TEST(DenoiseGuide, StopsAtTheFirstSurfaceThatIsNotSpecular) {
    const Scene scene = mirror_scene(0.5f);
    EmbreeAccel accel(scene);
    const LightSet lights(scene, nullptr);
    const RenderContext ctx{scene, accel, lights};
    const GuideRecord g = denoise_guide(ray_along({0, 0, -1}), ctx, 7);
    expect_near(g.albedo, kTint, 1e-6f, "albedo");
    expect_near(g.normal, normalize(Vec3(1, 0, 1)), 1e-5f, "normal");
    EXPECT_NEAR(g.depth, 2.0f, 1e-4f);
    // The wall seen directly (the ray runs parallel to the metal, past it).
    const GuideRecord w = denoise_guide(ray_along(normalize(Vec3(1, 0, -1))), ctx, 7);
    expect_near(w.albedo, kWall, 1e-6f, "wall albedo");
    expect_near(w.normal, {-1, 0, 0}, 1e-5f, "wall normal");
    EXPECT_NEAR(w.depth, 2 * std::sqrt(2.0f), 1e-4f);
}

TEST(DenoiseGuide, AnEscapedRayLeavesZeros) {
    const Scene scene = mirror_scene(0);
    EmbreeAccel accel(scene);
    const LightSet lights(scene, nullptr);
    const RenderContext ctx{scene, accel, lights};
    const GuideRecord g = denoise_guide(ray_along({0, 0, 1}), ctx, 1);
    expect_near(g.albedo, Spectrum(0), 0, "albedo");
    expect_near(g.normal, Vec3(0), 0, "normal");
    EXPECT_EQ(g.depth, 0);
    // A mirror that shows nothing: zeros too.
    const Scene alone = mirror_scene(0, false);
    EmbreeAccel alone_accel(alone);
    const LightSet alone_lights(alone, nullptr);
    const RenderContext alone_ctx{alone, alone_accel, alone_lights};
    const GuideRecord m = denoise_guide(ray_along({0, 0, -1}), alone_ctx, 1);
    expect_near(m.albedo, Spectrum(0), 0, "albedo");
    EXPECT_EQ(m.depth, 0);
}

}  // namespace
}  // namespace penumbra
