// The path and direct integrators on scenes with exact answers, for every light
// strategy and sampler: the estimates must agree with the analytic value (t-test).
#include "integrators/path_integrator.h"

#include <gtest/gtest.h>

#include <cstring>

#include "core/accel/embree_accel.h"
#include "core/lights/point_light.h"
#include "core/sampling/warp.h"
#include "support/statistics/estimate.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

struct TestScene {
    Scene scene;
    std::unique_ptr<EmbreeAccel> accel;
    std::unique_ptr<LightSet> lights;
    RenderContext ctx() const { return {scene, *accel, *lights}; }
};

// The inside of a closed box whose walls all emit Le and reflect albedo a
// (Lambertian): radiance is Le / (1 - a) everywhere, in every direction.
std::unique_ptr<TestScene> furnace_box(float Le, float a) {
    auto s = std::make_unique<TestScene>();
    MaterialDesc m;
    m.base_color = Vec4(Spectrum(a), 1);
    m.metallic = 0;
    m.specular = 0;
    m.emissive = Spectrum(Le);
    m.double_sided = true;  // the cube winds outwards: its back faces emit into the box
    s->scene.materials.push_back(m);
    const uint32_t cube = test::add_cube_object(s->scene, 0);
    test::add_instance(s->scene, cube, Transform::scale({2, 3, 4}));
    s->accel = std::make_unique<EmbreeAccel>(s->scene);
    s->lights = std::make_unique<LightSet>(s->scene, nullptr);
    return s;
}

// A convex Lambertian box of albedo a under a uniform environment L: every point sees
// the whole environment over its hemisphere, so the radiance leaving it is a * L.
std::unique_ptr<TestScene> box_in_environment(float a, float L) {
    auto s = std::make_unique<TestScene>();
    const int mat = test::add_lambertian(s->scene, Spectrum(a));
    const uint32_t cube = test::add_cube_object(s->scene, mat);
    test::add_instance(s->scene, cube, Transform::rotate({0.2f, 0.3f, 0.1f, 0.9f}));
    s->accel = std::make_unique<EmbreeAccel>(s->scene);
    s->lights = std::make_unique<LightSet>(
        s->scene, std::make_unique<EnvironmentLight>(Spectrum(L), 1.0f));
    return s;
}

// Radiance along rays from `origin` in directions spread over the sphere, one sample
// per ray, through the given sampler.
test::Estimate measure(const TestScene& s, const Integrator& integrator, SamplerType type,
                       Vec3 origin, bool look_at_origin, uint64_t n) {
    const uint32_t spp = 64;
    auto sampler = make_sampler(type, spp, 7);
    const RenderContext ctx = s.ctx();
    return test::estimate(n, [&](uint64_t i) {
        sampler->start_pixel_sample({int(i / spp), 0}, uint32_t(i % spp));
        Ray r;
        const Vec3 d = square_to_uniform_sphere(sampler->get_2d());
        if (look_at_origin) {
            r.o = origin + d * 5.0f;
            r.d = -d;
        } else {
            r.o = origin;
            r.d = d;
        }
        return integrator.Li(r, ctx, *sampler).y;
    });
}

TEST(PathIntegrator, FurnaceBoxRadianceIsEmissionOverOneMinusAlbedo) {
    const float Le = 1, a = 0.5f;
    const auto s = furnace_box(Le, a);
    for (LightStrategy strategy :
         {LightStrategy::Mis, LightStrategy::BsdfOnly, LightStrategy::LightOnly}) {
        for (SamplerType type : {SamplerType::Independent, SamplerType::Stratified,
                                 SamplerType::Sobol, SamplerType::ZSobol,
                                 SamplerType::TabledSobol}) {
            IntegratorOptions opt;
            opt.max_depth = 200;
            opt.strategy = strategy;
            const PathIntegrator integrator(opt);
            const test::Estimate e =
                measure(*s, integrator, type, {0.1f, -0.2f, 0.3f}, false, 20000);
            EXPECT_TRUE(test::within(e, Le / (1 - a)))
                << "strategy " << int(strategy) << " sampler " << int(type) << ": " << e.mean
                << " +- " << e.std_error << ", expected " << Le / (1 - a);
            // Power: a 10% bias must stand out by several standard errors.
            EXPECT_LT(e.std_error, 0.02 * Le / (1 - a));
        }
    }
}

TEST(PathIntegrator, ConvexBoxUnderUniformEnvironmentReflectsAlbedoTimesL) {
    const float a = 0.6f, L = 1.5f;
    const auto s = box_in_environment(a, L);
    for (LightStrategy strategy :
         {LightStrategy::Mis, LightStrategy::BsdfOnly, LightStrategy::LightOnly}) {
        IntegratorOptions opt;
        opt.strategy = strategy;
        const PathIntegrator integrator(opt);
        // Rays aimed at the box centre from all around: each hits the box.
        const test::Estimate e =
            measure(*s, integrator, SamplerType::Stratified, {0, 0, 0}, true, 20000);
        EXPECT_TRUE(test::within(e, a * L))
            << "strategy " << int(strategy) << ": " << e.mean << " +- " << e.std_error;
    }
}

TEST(DirectIntegrator, ConvexBoxUnderUniformEnvironmentMatchesForAnySampleSplit) {
    const float a = 0.6f, L = 1.5f;
    const auto s = box_in_environment(a, L);
    for (auto [nl, nb] : {std::pair{1, 1}, {4, 0}, {0, 4}, {3, 2}}) {
        IntegratorOptions opt;
        opt.light_samples = nl;
        opt.bsdf_samples = nb;
        const auto integrator = make_integrator(IntegratorType::Direct, opt);
        const test::Estimate e =
            measure(*s, *integrator, SamplerType::Independent, {0, 0, 0}, true, 10000);
        EXPECT_TRUE(test::within(e, a * L))
            << nl << " light, " << nb << " bsdf samples: " << e.mean << " +- " << e.std_error;
    }
}

// A closed Lambertian box lit by a point light inside it: nothing a ray can hit emits,
// so each path ends at its last light sample instead of tracing one more ray to find
// emission. The radiance must be the same bits as with that ray traced (a context told
// that something emits), and the saving exactly one ray per path (Russian roulette off,
// so every path reaches the last depth).
TEST(PathIntegrator, EndsAtTheLastLightSampleWhereNoSurfaceOrEnvironmentEmits) {
    TestScene s;
    const int mat = test::add_lambertian(s.scene, Spectrum(0.7f));
    const uint32_t cube = test::add_cube_object(s.scene, mat);
    test::add_instance(s.scene, cube, Transform::scale({2, 3, 4}));
    s.scene.lights.push_back(std::make_unique<PointLight>(Vec3{0.3f, 1, -0.5f}, Spectrum(10)));
    s.accel = std::make_unique<EmbreeAccel>(s.scene);
    s.lights = std::make_unique<LightSet>(s.scene, nullptr);
    // The rays start inside the box, which faces out: radiance along them, not camera rays.
    RenderContext early = s.ctx();
    early.camera_culling = false;
    ASSERT_FALSE(early.has_emission);
    RenderContext full = early;
    full.has_emission = true;  // as if some surface emitted: every path's last ray traced

    const uint32_t spp = 16, n = 4000;
    for (int max_depth : {1, 2, 5}) {
        IntegratorOptions opt;
        opt.max_depth = max_depth;
        opt.rr_depth = 1000;
        const PathIntegrator integrator(opt);
        auto sampler = make_sampler(SamplerType::TabledSobol, spp, 3);
        uint64_t rays[2] = {0, 0};
        double sum = 0;
        for (uint32_t i = 0; i < n; ++i) {
            Spectrum L[2];
            for (int k = 0; k < 2; ++k) {
                sampler->start_pixel_sample({int(i / spp), 0}, i % spp);
                Ray r;
                r.o = {0.1f, -0.2f, 0.3f};
                r.d = square_to_uniform_sphere(sampler->get_2d());
                const uint64_t before = s.accel->rays_traced();
                L[k] = integrator.Li(r, k == 0 ? early : full, *sampler);
                rays[k] += s.accel->rays_traced() - before;
            }
            ASSERT_EQ(std::memcmp(&L[0], &L[1], sizeof(Spectrum)), 0)
                << "max_depth " << max_depth << ", path " << i << ": " << L[0].y << " against "
                << L[1].y;
            sum += L[0].y;
        }
        EXPECT_GT(sum, 0) << "max_depth " << max_depth;  // the light reaches the walls
        EXPECT_EQ(rays[1] - rays[0], n) << "max_depth " << max_depth;
        // A camera ray, then a light sample and a ray per bounce, the last ray left out.
        EXPECT_EQ(rays[0], uint64_t(n) * 2 * max_depth) << "max_depth " << max_depth;
    }

    // Emissive surfaces and environments keep the last ray: it can find their light. A
    // convex box under an environment at depth 1: under MIS, much of the light a * L
    // comes through that ray.
    EXPECT_TRUE(furnace_box(1, 0.5f)->ctx().has_emission);
    const auto env = box_in_environment(0.6f, 1.5f);
    ASSERT_FALSE(env->ctx().has_emission);
    IntegratorOptions one_bounce;
    one_bounce.max_depth = 1;
    const PathIntegrator integrator(one_bounce);
    const test::Estimate e =
        measure(*env, integrator, SamplerType::Stratified, {0, 0, 0}, true, 20000);
    EXPECT_TRUE(test::within(e, 0.6f * 1.5f)) << e.mean << " +- " << e.std_error;
    Scene unlit;
    MaterialDesc m;
    m.unlit = true;
    unlit.materials.push_back(m);
    EXPECT_TRUE(scene_has_emission(unlit));
    unlit.materials[0].unlit = false;
    EXPECT_FALSE(scene_has_emission(unlit));
}

TEST(PathIntegrator, MisHasLowerVarianceThanEitherStrategyAloneOnASmallLight) {
    // A small emissive square above a diffuse floor: light sampling wins; MIS must be
    // close to it and far better than BSDF sampling.
    auto s = std::make_unique<TestScene>();
    const int floor_mat = test::add_lambertian(s->scene, Spectrum(0.8f));
    MaterialDesc emitter;
    emitter.base_color = Vec4(0, 0, 0, 1);
    emitter.metallic = 0;
    emitter.specular = 0;
    emitter.emissive = Spectrum(50);
    s->scene.materials.push_back(emitter);
    const uint32_t floor_obj = test::add_quad_object(s->scene, {-10, 0, 10}, {10, 0, 10},
                                                     {10, 0, -10}, {-10, 0, -10}, floor_mat);
    const float h = 0.1f;
    const uint32_t light_obj = test::add_quad_object(s->scene, {-h, 2, -h}, {h, 2, -h},
                                                     {h, 2, h}, {-h, 2, h}, 1);
    test::add_instance(s->scene, floor_obj, Transform());
    test::add_instance(s->scene, light_obj, Transform());
    s->accel = std::make_unique<EmbreeAccel>(s->scene);
    s->lights = std::make_unique<LightSet>(s->scene, nullptr);

    auto run = [&](LightStrategy strategy) {
        IntegratorOptions opt;
        opt.strategy = strategy;
        opt.max_depth = 1;
        const PathIntegrator integrator(opt);
        auto sampler = make_sampler(SamplerType::Independent, 1, 3);
        const RenderContext ctx = s->ctx();
        return test::estimate(40000, [&](uint64_t i) {
            sampler->start_pixel_sample({int(i), 0}, 0);
            Ray r;
            r.o = {0.3f, 1, 0.2f};
            r.d = {0, -1, 0};
            return integrator.Li(r, ctx, *sampler).x;
        });
    };
    const test::Estimate mis = run(LightStrategy::Mis), bsdf = run(LightStrategy::BsdfOnly),
                         light = run(LightStrategy::LightOnly);
    // All three are unbiased estimates of the same value.
    const double diff_bl = std::abs(bsdf.mean - light.mean);
    EXPECT_LT(diff_bl, 4 * std::hypot(bsdf.std_error, light.std_error));
    EXPECT_LT(std::abs(mis.mean - light.mean), 4 * std::hypot(mis.std_error, light.std_error));
    EXPECT_LT(mis.std_error, 0.5 * bsdf.std_error);
    EXPECT_LT(mis.std_error, 1.5 * light.std_error);
}

}  // namespace
}  // namespace penumbra
