// End-to-end renders of scenes with a known answer, and the determinism property.
#include "integrators/render.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstring>

#include "core/accel/embree_accel.h"
#include "core/camera/perspective_camera.h"
#include "core/lights/directional_light.h"
#include "core/lights/point_light.h"
#include "support/scene_builder.h"
#include "support/option_names.h"
#include "job/aov_list.h"

namespace penumbra {
namespace {

// A large Lambertian floor (y = 0) of albedo 0.5 under a directional light of
// irradiance E at 60 degrees from the normal, seen from above.
Scene lit_plane(float E, float light_angle) {
    Scene scene;
    const int mat = test::add_lambertian(scene, Spectrum(0.5f));
    const float s = 100;
    const uint32_t quad =
        test::add_quad_object(scene, {-s, 0, s}, {s, 0, s}, {s, 0, -s}, {-s, 0, -s}, mat);
    test::add_instance(scene, quad, Transform());
    const Vec3 travel(std::sin(light_angle), -std::cos(light_angle), 0);
    scene.lights.push_back(std::make_unique<DirectionalLight>(travel, Spectrum(E), s));
    return scene;
}

TEST(Render, LambertianPlaneUnderDirectionalLightMatchesAnalyticRadiance) {
    const float E = 3.0f, angle = kPi / 3;
    const Scene scene = lit_plane(E, angle);
    EmbreeAccel accel(scene);
    const LightSet lights(scene, nullptr);
    const RenderContext ctx{scene, accel, lights};
    const PerspectiveCamera camera(Transform::look_at({0, 5, 0.01f}, {0, 0, 0}, {0, 1, 0}),
                                   0.8f, 32, 24);
    RenderOptions opt;
    opt.spp = 4;
    opt.progress = false;
    // Point and directional light are found only by light sampling, so every integrator
    // gives the exact answer.
    for (const char* name : {"basic", "direct", "path"}) {
    const auto integrator = make_integrator(test::integrator_named(name), {});
    const Image img = render(ctx, camera, *integrator, opt).resolve();
    // L = albedo / pi * E * cos(theta)
    const float expected = 0.5f / kPi * E * std::cos(angle);
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            for (int c = 0; c < 3; ++c) ASSERT_NEAR(img.at(x, y)[c], expected, 1e-5f) << name;
    }
}

TEST(Render, PointLightFalloffIsInverseSquare) {
    Scene scene;
    const int mat = test::add_lambertian(scene, Spectrum(1.0f));
    const uint32_t quad = test::add_quad_object(scene, {-50, 0, 50}, {50, 0, 50},
                                                {50, 0, -50}, {-50, 0, -50}, mat);
    test::add_instance(scene, quad, Transform());
    const float I = 10, h = 2;
    scene.lights.push_back(std::make_unique<PointLight>(Vec3(0, h, 0), Spectrum(I)));
    EmbreeAccel accel(scene);
    const LightSet lights(scene, nullptr);
    const RenderContext ctx{scene, accel, lights};
    const auto integrator = make_integrator(IntegratorType::Basic, {});
    for (float x : {0.0f, 1.0f, 3.0f}) {
        Ray r;
        r.o = {x, 1, 0.001f};
        r.d = {0, -1, 0};
        IndependentSampler sampler(1, 0);
        sampler.start_pixel_sample({0, 0}, 0);
        const Spectrum L = integrator->Li(r, ctx, sampler);
        const float d2 = x * x + h * h;
        const float cos_theta = h / std::sqrt(d2);
        EXPECT_NEAR(L.x, 1.0f / kPi * I / d2 * cos_theta, 1e-5f) << "x = " << x;
    }
}

TEST(Render, ImagesAreBitwiseIdenticalAcrossThreadCounts) {
    Scene scene = lit_plane(2.0f, 0.3f);
    const int mat = test::add_lambertian(scene, Spectrum(0.8f, 0.2f, 0.1f));
    const uint32_t cube = test::add_cube_object(scene, mat);
    test::add_instance(scene, cube, Transform::trs({0, 0.5f, 0}, Quat{0, 0.38f, 0, 0.92f}, {1, 1, 1}));
    EmbreeAccel accel(scene);
    const LightSet lights(scene, nullptr);
    const RenderContext ctx{scene, accel, lights};
    const PerspectiveCamera camera(Transform::look_at({2, 3, 4}, {0, 0.3f, 0}, {0, 1, 0}), 0.7f,
                                   40, 30);
    const auto integrator = make_integrator(IntegratorType::Path, {});
    RenderOptions opt;
    opt.spp = 5;
    opt.seed = 1234;
    opt.progress = false;
    opt.tile_size = 7;
    for (SamplerType type :
         {SamplerType::Independent, SamplerType::Stratified, SamplerType::ZSobol}) {
        opt.sampler = type;
        opt.threads = 1;
        const Image a = render(ctx, camera, *integrator, opt).resolve();
        opt.threads = 2;
        const Image b = render(ctx, camera, *integrator, opt).resolve();
        opt.threads = 3;
        opt.tile_size = 5;
        const Image c = render(ctx, camera, *integrator, opt).resolve();
        opt.tile_size = 7;
        ASSERT_EQ(a.pixels.size(), b.pixels.size());
        EXPECT_EQ(0, std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * 4));
        EXPECT_EQ(0, std::memcmp(a.pixels.data(), c.pixels.data(), a.pixels.size() * 4));
        // A different seed gives a different image (the anti-aliased cube edges differ).
        opt.seed = 99;
        opt.threads = 1;
        const Image d = render(ctx, camera, *integrator, opt).resolve();
        opt.seed = 1234;
        EXPECT_NE(0, std::memcmp(a.pixels.data(), d.pixels.data(), a.pixels.size() * 4));
    }
}

// A scene with edges (anti-aliasing) and indirect light, so every sample matters.
Scene cube_on_plane() {
    Scene scene = lit_plane(2.0f, 0.3f);
    const int mat = test::add_lambertian(scene, Spectrum(0.8f, 0.2f, 0.1f));
    const uint32_t cube = test::add_cube_object(scene, mat);
    test::add_instance(scene, cube, Transform::trs({0, 0.5f, 0}, Quat{0, 0.38f, 0, 0.92f}, {1, 1, 1}));
    return scene;
}

TEST(Render, PassesAddUpToTheSameImageBitForBit) {
    const Scene scene = cube_on_plane();
    EmbreeAccel accel(scene);
    const LightSet lights(scene, nullptr);
    const RenderContext ctx{scene, accel, lights};
    const PerspectiveCamera camera(Transform::look_at({2, 3, 4}, {0, 0.3f, 0}, {0, 1, 0}), 0.7f,
                                   24, 18);
    const auto integrator = make_integrator(IntegratorType::Path, {});
    RenderOptions opt;
    opt.spp = 7;
    opt.progress = false;
    for (SamplerType type : {SamplerType::Independent, SamplerType::Stratified, SamplerType::Sobol,
                             SamplerType::ZSobol}) {
        opt.sampler = type;
        Film whole(24, 18), split(24, 18);
        ASSERT_TRUE(render_samples(ctx, camera, *integrator, opt, whole, 0, 7));
        ASSERT_TRUE(render_samples(ctx, camera, *integrator, opt, split, 0, 3));
        ASSERT_TRUE(render_samples(ctx, camera, *integrator, opt, split, 3, 7));
        RenderStats stats;
        const Image passes = render(ctx, camera, *integrator, opt, &stats).resolve();
        EXPECT_EQ(stats.spp, 7u);
        EXPECT_GT(stats.passes, 1);  // render() itself works in passes
        const Image a = whole.resolve(), b = split.resolve();
        EXPECT_EQ(0, std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * 4));
        EXPECT_EQ(0, std::memcmp(a.pixels.data(), passes.pixels.data(), a.pixels.size() * 4));
        // Not vacuous: a pass of the other samples alone differs.
        Film tail(24, 18);
        ASSERT_TRUE(render_samples(ctx, camera, *integrator, opt, tail, 3, 7));
        const Image c = tail.resolve();
        EXPECT_NE(0, std::memcmp(a.pixels.data(), c.pixels.data(), a.pixels.size() * 4));
    }
}

// The path tracer, made to take no traced first hit: the render loop then traces every
// camera ray on its own.
class SingleRayPath final : public Integrator {
public:
    Spectrum Li(const Ray& ray, const RenderContext& ctx, Sampler& sampler) const override {
        return m_path->Li(ray, ctx, sampler);
    }

private:
    std::unique_ptr<Integrator> m_path = make_integrator(IntegratorType::Path, {});
};

TEST(Render, CameraPacketsGiveTheImageOfSingleRays) {
    const Scene scene = cube_on_plane();
    const auto path = make_integrator(IntegratorType::Path, {});
    ASSERT_TRUE(path->uses_first_hit());
    const SingleRayPath single;
    // 26 x 18 in tiles of 7: full 4 x 2 blocks (packets) and partial ones (single rays).
    const PerspectiveCamera camera(Transform::look_at({2, 3, 4}, {0, 0.3f, 0}, {0, 1, 0}), 0.7f,
                                   26, 18);
    RenderOptions opt;
    opt.spp = 3;
    opt.seed = 7;
    opt.progress = false;
    opt.tile_size = 7;
    opt.threads = 2;
    for (AccelType type : {AccelType::Embree, AccelType::BvhSah}) {
        const std::unique_ptr<Accel> accel = make_accel(type, scene);
        const LightSet lights(scene, nullptr);
        const RenderContext ctx{scene, *accel, lights};
        RenderStats a_stats, b_stats;
        const Image a = render(ctx, camera, *path, opt, &a_stats).resolve();
        const Image b = render(ctx, camera, single, opt, &b_stats).resolve();
        ASSERT_EQ(a.pixels.size(), b.pixels.size());
        EXPECT_EQ(0, std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * 4))
            << accel_type_name(type);
        EXPECT_EQ(a_stats.rays, b_stats.rays) << accel_type_name(type);
    }
}

TEST(Render, InterruptsAndTimeLimitStopBetweenPasses) {
    const Scene scene = cube_on_plane();
    EmbreeAccel accel(scene);
    const LightSet lights(scene, nullptr);
    const RenderContext ctx{scene, accel, lights};
    const PerspectiveCamera camera(Transform::look_at({2, 3, 4}, {0, 0.3f, 0}, {0, 1, 0}), 0.7f,
                                   16, 12);
    const auto integrator = make_integrator(IntegratorType::Path, {});
    RenderOptions opt;
    opt.spp = 64;
    opt.progress = false;
    std::atomic<int> interrupts{1};
    opt.interrupts = &interrupts;
    RenderStats stats;
    render(ctx, camera, *integrator, opt, &stats);
    EXPECT_EQ(stats.spp, 0u);  // asked to stop before the first pass
    EXPECT_TRUE(stats.interrupted);
    EXPECT_FALSE(stats.aborted);
    interrupts = 2;  // a second Ctrl-C abandons even the pass under way
    Film film(16, 12);
    EXPECT_FALSE(render_samples(ctx, camera, *integrator, opt, film, 0, 4));

    // A time limit already spent still renders the first pass, and only that.
    opt.interrupts = nullptr;
    opt.time_limit = 1e-9;
    render(ctx, camera, *integrator, opt, &stats);
    EXPECT_EQ(stats.spp, 1u);
    EXPECT_EQ(stats.passes, 1);
    EXPECT_FALSE(stats.interrupted);
}

TEST(Render, AdaptiveRenderStopsOnlyAfterWholeFixedPasses) {
    const Scene scene = cube_on_plane();
    EmbreeAccel accel(scene);
    const LightSet lights(scene, nullptr);
    const RenderContext ctx{scene, accel, lights};
    const PerspectiveCamera camera(Transform::look_at({2, 3, 4}, {0, 0.3f, 0}, {0, 1, 0}), 0.7f,
                                   24, 18);
    const auto integrator = make_integrator(IntegratorType::Path, {});
    RenderOptions opt;
    opt.spp = 256;
    opt.progress = false;
    opt.target_error = 0.01;  // not reached at 256 spp
    // A time limit already spent still renders the first pass, the minimum, and stops
    // there; the film is exactly the first min_spp samples of every pixel.
    opt.time_limit = 1e-9;
    RenderStats stats;
    const Film film = render(ctx, camera, *integrator, opt, &stats);
    EXPECT_EQ(stats.spp, 64u);  // adaptive_min_spp(0.01)
    EXPECT_EQ(stats.passes, 1);
    EXPECT_EQ(stats.camera_samples, 24u * 18u * 64u);
    Film direct(24, 18, parse_aovs("error,samples"));
    ASSERT_TRUE(render_samples(ctx, camera, *integrator, opt, direct, 0, 64));
    const Image a = film.resolve(), b = direct.resolve();
    EXPECT_EQ(0, std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * 4));
    EXPECT_EQ(film.resolve_aov(Aov::Error).pixels, direct.resolve_aov(Aov::Error).pixels);
    // An interrupt before the first pass renders nothing.
    std::atomic<int> interrupts{1};
    opt.interrupts = &interrupts;
    opt.time_limit = 0;
    render(ctx, camera, *integrator, opt, &stats);
    EXPECT_EQ(stats.spp, 0u);
    EXPECT_TRUE(stats.interrupted);
}

TEST(Render, PassSizesDoubleWithinTheBudgetPassLengthAndTimeLimit) {
    EXPECT_EQ(next_pass_samples(0, 16, 0, 0), 1u);
    EXPECT_EQ(next_pass_samples(1, 16, 0.01, 0), 1u);
    EXPECT_EQ(next_pass_samples(2, 16, 0.02, 0), 2u);
    EXPECT_EQ(next_pass_samples(4, 16, 0.04, 0), 4u);
    EXPECT_EQ(next_pass_samples(8, 10, 0.08, 0), 2u);   // the budget
    EXPECT_EQ(next_pass_samples(16, 16, 0.16, 0), 0u);  // done
    // 1 s per sample: passes of at most 2 s, so Ctrl-C is answered within one.
    EXPECT_EQ(next_pass_samples(8, 100, 8, 0, 2.0), 2u);
    EXPECT_EQ(next_pass_samples(8, 100, 80, 0, 2.0), 1u);  // at least one sample
    // Time limit: nothing that is predicted to end after it.
    EXPECT_EQ(next_pass_samples(4, 100, 4, 7.5, 10.0), 3u);
    EXPECT_EQ(next_pass_samples(4, 100, 4, 4.9, 10.0), 0u);
    EXPECT_EQ(next_pass_samples(0, 100, 0, 1e-9), 1u);  // the first pass always runs
}

}  // namespace
}  // namespace penumbra
