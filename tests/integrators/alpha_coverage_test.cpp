// Coverage (glTF alphaMode MASK and BLEND) in the integrators: shadow rays carry the
// product of the transparencies they cross, a camera path shades a surface's coverage as
// a weight before one coin sends it through or on by the BSDF, and an emitter with alpha
// sends light by its coverage. The first two are exact, so each sample must equal the
// known value (a coin flip anywhere would make samples 0 or the whole); the white
// furnace checks that the coin and the weights together stay unbiased.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/accel/embree_accel.h"
#include "core/lights/point_light.h"
#include "core/scene/coverage.h"
#include "integrators/integrator.h"
#include "support/statistics/estimate.h"
#include "support/irradiance.h"
#include "support/scene_builder.h"
#include "support/option_names.h"

namespace penumbra {
namespace {

struct BlendScene {
    Scene scene;
    std::unique_ptr<EmbreeAccel> accel;
    std::unique_ptr<LightSet> lights;
    RenderContext context() const {
        return RenderContext{scene, *accel, *lights, scene_has_alpha(scene)};
    }
};

void finish(BlendScene& s, std::unique_ptr<EnvironmentLight> env = nullptr) {
    s.accel = std::make_unique<EmbreeAccel>(s.scene);
    s.lights = std::make_unique<LightSet>(s.scene, std::move(env));
}

// A Lambertian material of constant alpha (BLEND unless told otherwise).
int add_blend(Scene& scene, Spectrum albedo, float alpha, AlphaMode mode = AlphaMode::Blend) {
    const int m = test::add_lambertian(scene, albedo);
    scene.materials[m].base_color.w = alpha;
    scene.materials[m].alpha_mode = mode;
    return m;
}

TEST(AlphaCoverage, FollowsTheAlphaModes) {
    MaterialDesc m;
    m.alpha_cutoff = 0.3f;
    for (const float alpha : {-0.5f, 0.0f, 0.29f, 0.3f, 0.8f, 1.5f}) {
        m.alpha_mode = AlphaMode::Opaque;
        EXPECT_EQ(coverage_from_alpha(m, alpha), 1.0f) << alpha;
        m.alpha_mode = AlphaMode::Mask;  // glTF: rendered where alpha >= alphaCutoff
        EXPECT_EQ(coverage_from_alpha(m, alpha), alpha >= 0.3f ? 1.0f : 0.0f) << alpha;
        m.alpha_mode = AlphaMode::Blend;
        EXPECT_EQ(coverage_from_alpha(m, alpha), std::clamp(alpha, 0.0f, 1.0f)) << alpha;
    }
    // The factor's alpha times COLOR_0's.
    Scene scene;
    m.alpha_mode = AlphaMode::Blend;
    m.base_color = {1, 1, 1, 0.5f};
    EXPECT_FLOAT_EQ(material_coverage(scene, m, {}, {}, 0.6f), 0.3f);
    m.alpha_mode = AlphaMode::Mask;
    EXPECT_EQ(material_coverage(scene, m, {}, {}, 0.58f), 0.0f);
    EXPECT_EQ(material_coverage(scene, m, {}, {}, 0.62f), 1.0f);
}

// A horizontal square of half side 20 at height y, facing up.
void add_plane(Scene& s, float y, int material) {
    test::add_instance(
        s,
        test::add_quad_object(s, {-20, y, 20}, {20, y, 20}, {20, y, -20}, {-20, y, -20}, material),
        Transform());
}

// n path samples along `ray`, each from its own sample index.
std::vector<float> samples(const BlendScene& s, const Ray& ray, int n, IntegratorOptions o = {},
                           const std::string& integrator_name = "path") {
    const auto integrator = make_integrator(test::integrator_named(integrator_name), o);
    auto sampler = make_sampler(SamplerType::TabledSobol, 64, 3);
    const RenderContext ctx = s.context();
    std::vector<float> v;
    for (int i = 0; i < n; ++i) {
        sampler->start_pixel_sample({0, 0}, i);
        v.push_back(integrator->Li(ray, ctx, *sampler).y);
    }
    return v;
}

// n independent samples of one ray, each from its own pixel of an independent sampler.
test::Estimate estimate_ray(const BlendScene& s, const std::string& integrator_name,
                            const IntegratorOptions& o, Vec3 origin, Vec3 dir, uint64_t seed) {
    const auto integrator = make_integrator(test::integrator_named(integrator_name), o);
    auto sampler = make_sampler(SamplerType::Independent, 1, seed);
    const RenderContext ctx = s.context();
    return test::estimate(40000, [&](uint64_t i) {
        sampler->start_pixel_sample({int(i), 0}, 0);
        Ray r;
        r.o = origin;
        r.d = dir;
        return integrator->Li(r, ctx, *sampler).y;
    });
}

// A Lambertian floor lit by a point light 2 above it, through sheets at heights 1 and
// 1.5 of the given coverages; the camera ray starts between the floor and the sheets.
TEST(AlphaCoverage, ShadowRaysCarryTheProductOfTransparencies) {
    const float albedo = 0.5f, intensity = 3;
    struct Case {
        float a1, a2;
        AlphaMode mode1 = AlphaMode::Blend;  // of the lower sheet
        float coverage1 = a1;
    };
    for (const Case c : {Case{0.3f, 0.5f}, Case{0.3f, 0.0f}, Case{1.0f, 0.5f}, Case{0, 0},
                         Case{0.4f, 0.5f, AlphaMode::Mask, 0}, Case{0.6f, 0.5f, AlphaMode::Mask, 1},
                         Case{0.4f, 0.5f, AlphaMode::Opaque, 1}}) {
        BlendScene s;
        add_plane(s.scene, 0, test::add_lambertian(s.scene, Spectrum(albedo)));
        add_plane(s.scene, 1, add_blend(s.scene, Spectrum(0.8f), c.a1, c.mode1));
        add_plane(s.scene, 1.5f, add_blend(s.scene, Spectrum(0.8f), c.a2));
        s.scene.lights.push_back(std::make_unique<PointLight>(Vec3{0, 2, 0}, Spectrum(intensity)));
        finish(s);
        ASSERT_TRUE(s.context().has_alpha);
        for (const Vec3 p : {Vec3{0, 0, 0}, Vec3{0.7f, 0, -0.4f}}) {
            Ray ray;
            ray.o = p + Vec3{0, 0.5f, 0};
            ray.d = {0, -1, 0};
            const Vec3 to_light = Vec3{0, 2, 0} - p;
            const float d2 = dot(to_light, to_light), cos = to_light.y / std::sqrt(d2);
            const float expected =
                albedo / kPi * intensity * cos / d2 * (1 - c.coverage1) * (1 - c.a2);
            IntegratorOptions o;
            o.max_depth = 1;  // direct light only
            for (const char* integrator : {"path", "direct", "basic"})
                for (const float v : samples(s, ray, 64, o, integrator))
                    ASSERT_NEAR(v, expected, 1e-5f * intensity)
                        << integrator << ", alphas " << c.a1 << " (mode " << int(c.mode1) << "), "
                        << c.a2 << " at " << p.x << ", " << p.z;
        }
    }
}

// A sheet of coverage 0.4 in front of the camera over a black background: its emission
// and the light it reflects from a point light in front count 0.4 of their whole in
// every sample, however the coin then sends the path on (path tracing, distribution ray
// tracing and the classic ray tracer alike).
TEST(AlphaCoverage, CameraPathsShadeTheCoveredShareInEverySample) {
    const float alpha = 0.4f, albedo = 0.8f, emission = 2, intensity = 5;
    for (const bool emissive : {true, false}) {
        BlendScene s;
        const int m = add_blend(s.scene, Spectrum(emissive ? 0.0f : albedo), alpha);
        if (emissive) s.scene.materials[m].emissive = Spectrum(emission);
        test::add_instance(
            s.scene,
            test::add_quad_object(s.scene, {-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}, m),
            Transform());
        if (!emissive)
            s.scene.lights.push_back(
                std::make_unique<PointLight>(Vec3{0, 0, 2}, Spectrum(intensity)));
        finish(s);
        Ray ray;
        ray.o = {0.1f, -0.2f, 5};
        ray.d = {0, 0, -1};
        const Vec3 p{0.1f, -0.2f, 0}, to_light = Vec3{0, 0, 2} - p;
        const float d2 = dot(to_light, to_light);
        const float expected =
            emissive ? alpha * emission
                     : alpha * albedo / kPi * intensity * (to_light.z / std::sqrt(d2)) / d2;
        for (const char* integrator : {"path", "direct", "basic"})
            for (const float v : samples(s, ray, 64, {}, integrator))
                ASSERT_NEAR(v, expected, 1e-5f)
                    << integrator << (emissive ? ", emissive" : ", lit");
    }
}

// A square emitter of radiance 2 facing a Lambertian floor from height 1, of coverage
// 0.4 itself or opaque behind a sheet of coverage 0.6 at height 0.5: the floor under its
// centre sees 0.4 of the analytic irradiance, whether light sampling finds the emitter,
// BSDF sampling, or both under MIS. (Light sampling that counts an emitter's whole
// radiance makes MIS give between 0.4 and 1 of it; BSDF samples of the direct integrator
// that stop at the sheet make it give less than 0.4.)
TEST(AlphaCoverage, EmittersLightByTheirCoverage) {
    const float albedo = 0.5f, emission = 2;
    for (const bool sheet : {false, true}) {
        BlendScene s;
        add_plane(s.scene, 0, test::add_lambertian(s.scene, Spectrum(albedo)));
        const int m = add_blend(s.scene, Spectrum(0), sheet ? 1.0f : 0.4f);
        s.scene.materials[m].emissive = Spectrum(emission);
        // Counter-clockwise from below: the front faces the floor.
        test::add_instance(s.scene,
                           test::add_quad_object(s.scene, {-0.5f, 1, -0.5f}, {0.5f, 1, -0.5f},
                                                 {0.5f, 1, 0.5f}, {-0.5f, 1, 0.5f}, m),
                           Transform());
        if (sheet) add_plane(s.scene, 0.5f, add_blend(s.scene, Spectrum(0.3f), 0.6f));
        finish(s);
        const double expected = 0.4 * albedo / kPi * test::square_irradiance(emission, 1, 1);
        struct Config {
            const char* integrator;
            LightStrategy strategy;
        };
        for (const Config c : {Config{"path", LightStrategy::Mis},
                               {"path", LightStrategy::LightOnly},
                               {"path", LightStrategy::BsdfOnly},
                               {"direct", LightStrategy::Mis}}) {
            IntegratorOptions o;
            o.strategy = c.strategy;
            o.max_depth = 1;
            const test::Estimate e = estimate_ray(s, c.integrator, o, {0, 0.25f, 0}, {0, -1, 0}, 7);
            EXPECT_TRUE(test::within(e, expected))
                << (sheet ? "behind a sheet, " : "covered, ") << c.integrator << " "
                << int(c.strategy) << ": " << e.mean << " +- " << e.std_error << ", expected "
                << expected;
            EXPECT_LT(e.std_error, (sheet ? 0.02 : 0.01) * expected)
                << (sheet ? "behind a sheet, " : "covered, ") << c.integrator << " "
                << int(c.strategy);
        }
    }
}

// White furnace: a white Lambertian sphere of coverage 0.3 under a uniform environment
// of radiance 1 is exactly as bright as the background, seen through its centre (two
// crossings, light sampled and BSDF sampled, coins at each). With light sampling's
// share weighed by coverage, the coin's odds must be the coverage: at odds p the mean
// is 1 + (coverage - p) times the light samples' MIS share, so a coverage of 0.5 could
// not tell a coin the wrong way round.
TEST(AlphaCoverage, PartlyCoveredWhiteSphereMatchesTheFurnace) {
    BlendScene s;
    test::add_instance(s.scene,
                       test::add_sphere_object(s.scene, add_blend(s.scene, Spectrum(1), 0.3f)),
                       Transform());
    finish(s, std::make_unique<EnvironmentLight>(Spectrum(1), 10.0f));
    for (LightStrategy strategy :
         {LightStrategy::Mis, LightStrategy::LightOnly, LightStrategy::BsdfOnly}) {
        IntegratorOptions o;
        o.max_depth = 256;
        o.strategy = strategy;
        const test::Estimate e = estimate_ray(s, "path", o, {0.05f, 0.1f, 5}, {0, 0, -1}, 11);
        EXPECT_TRUE(test::within(e, 1.0))
            << int(strategy) << ": " << e.mean << " +- " << e.std_error;
        // Power: light sampling's share counted whole instead of by its coverage gave
        // 1.13 under MIS and 1.74 with light sampling alone (measured at coverage 0.5),
        // dozens of standard errors. Light sampling alone is the noisy one: shadow rays
        // that the sphere itself shades.
        EXPECT_LT(e.std_error, strategy == LightStrategy::LightOnly ? 0.01 : 0.003)
            << int(strategy);
    }
}

}  // namespace
}  // namespace penumbra
