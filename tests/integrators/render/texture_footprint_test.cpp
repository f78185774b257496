// Texture filtering through the renderer: camera rays carry a ray cone, hits turn it
// into a footprint, materials read the texture over it. A distant checkerboard then
// renders at its mean with little noise at 4 spp, where finest-level lookups (a
// sampler without mipmaps) leave each sample black or white.
#include <gtest/gtest.h>

#include <cstring>

#include "core/accel/embree_accel.h"
#include "core/camera/camera.h"
#include "core/camera/perspective_camera.h"
#include "integrators/render.h"
#include "support/render_scene.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

// An unlit quad [-1, 1]^2 showing a 512 x 512 sRGB checkerboard of 4-texel checks (mean
// 0.5, code 188 from level 2 up: 0.5029), seen head-on from distance 2 by a 32 x 32
// camera whose pixels each cover about 8 x 8 texels (level 3).
Scene checker_scene(MipFilter mip) {
    Scene s;
    const int n = 512;
    TextureImage t(n, n, 1, TexelFormat::U8, true);
    uint8_t* p = static_cast<uint8_t*>(t.level0_data());
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) p[y * n + x] = (x / 4 + y / 4) % 2 ? 255 : 0;
    t.build_mips();
    s.images.push_back(std::move(t));
    Texture tex;
    tex.mip = mip;
    s.textures.push_back(tex);
    MaterialDesc m;
    m.unlit = true;
    m.base_color_texture.texture = 0;
    s.materials.push_back(m);
    const uint32_t q = test::add_quad_object(s, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, 0);
    test::add_instance(s, q, Transform());
    CameraDesc cam;
    cam.yfov = 0.5f;
    cam.to_world = Transform::translate({0, 0, 2});
    s.cameras.push_back(cam);
    return s;
}

struct PixelStats {
    double mean = 0, variance = 0;
};

PixelStats stats(const Image& img) {
    double sum = 0, sum2 = 0;
    const int n = img.width * img.height;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const double v = img.at(x, y)[0];
            sum += v;
            sum2 += v * v;
        }
    return {sum / n, sum2 / n - (sum / n) * (sum / n)};
}

TEST(TextureFootprint, DistantCheckerboardConvergesWithLessVariance) {
    const Scene filtered = checker_scene(MipFilter::Linear);
    const Scene finest = checker_scene(MipFilter::None);
    const auto camera = make_camera(filtered.cameras[0], 32, 32);
    const Image a = test::render_scene(filtered, *camera, "path", 4, 1).image;
    const Image b = test::render_scene(finest, *camera, "path", 4, 1).image;
    const PixelStats fa = stats(a), fb = stats(b);
    // Finest level: samples mostly black or white, about 0.25 / 4 a pixel.
    EXPECT_GT(fb.variance, 0.03);
    // Filtered: levels 3 and up are flat; a level of detail half a level too fine would
    // blend in level 2's checks (about 0.016). A ratio of 100 sits between.
    EXPECT_LT(fa.variance * 100, fb.variance) << fa.variance << " " << fb.variance;
    EXPECT_NEAR(fa.mean, 0.5, 0.005);
    EXPECT_NEAR(fb.mean, 0.5, 4 * std::sqrt(fb.variance / (32 * 32)) + 0.003);
    // Footprints depend on the ray alone: the same image on every run.
    const Image again = test::render_scene(filtered, *camera, "path", 4, 1).image;
    ASSERT_EQ(again.pixels.size(), a.pixels.size());
    EXPECT_EQ(std::memcmp(again.pixels.data(), a.pixels.data(), a.pixels.size() * sizeof(float)),
              0);
}

// Ray cones only choose texture levels (RenderContext::ray_cones): a scene without
// textures traces none, and its image is bitwise the one that cones would give.
TEST(TextureFootprint, ScenesWithoutTexturesTraceNoCones) {
    const Scene textured = checker_scene(MipFilter::Linear);
    const Scene plain = test::make_lit_sphere_on_floor();
    ASSERT_TRUE(plain.textures.empty());
    const EmbreeAccel accel(plain);
    const LightSet lights(plain, nullptr);
    const RenderContext without{plain, accel, lights};
    EXPECT_FALSE(without.ray_cones);
    EXPECT_TRUE((RenderContext{textured, accel, lights}.ray_cones));
    RenderContext with = without;
    with.ray_cones = true;
    const PerspectiveCamera camera(Transform::look_at({0, 0.5f, 4}, {0, 0, 0}, {0, 1, 0}), 0.8f, 24,
                                   16);
    const auto integrator = make_integrator(IntegratorType::Path, IntegratorOptions{});
    RenderOptions opt;
    opt.spp = 8;
    opt.progress = false;
    const Image a = render(without, camera, *integrator, opt).resolve();
    const Image b = render(with, camera, *integrator, opt).resolve();
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    EXPECT_EQ(std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)), 0);
}

}  // namespace
}  // namespace penumbra
