// Emitters that move within the shutter are light-sampled where they are at the ray's
// time: a floor lit by a sliding square light gets the same image from light sampling
// alone, BSDF sampling alone and MIS, and that image is the exact time-averaged
// irradiance. (Were moving emitters left out of light sampling, the light-only image
// would be black; were they sampled where they are at shutter open, it would be the
// wrong image.)
#include <gtest/gtest.h>

#include <cmath>

#include "core/accel/embree_accel.h"
#include "core/camera/orthographic_camera.h"
#include "core/lights/light_set.h"
#include "integrators/render.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

constexpr float kH = 2;       // light height above the floor
constexpr float kSide = 1;    // light side
constexpr float kTravel = 2;  // the light's centre moves from x = -1 to x = +1
constexpr int kW = 32, kHt = 8;
constexpr float kHalfX = 2, kHalfZ = 0.5f;

Scene sliding_light_scene() {
    Scene scene;
    const int floor = test::add_lambertian(scene, Spectrum(0.8f));
    const int emitter = test::add_lambertian(scene, Spectrum(0.0f));
    scene.materials[emitter].emissive = Spectrum(1.0f);
    test::add_instance(scene,
                       test::add_quad_object(scene, {-10, 0, 10}, {10, 0, 10}, {10, 0, -10},
                                             {-10, 0, -10}, floor),
                       Transform());
    const float h = kSide / 2;
    const uint32_t light = test::add_quad_object(scene, {-h, kH, -h}, {h, kH, -h}, {h, kH, h},
                                                 {-h, kH, h}, emitter);
    const uint32_t i = test::add_instance(scene, light, Transform::translate({-kTravel / 2, 0, 0}));
    scene.instances[i].motion = {Transform::translate({-kTravel / 2, 0, 0}),
                                 Transform::translate({kTravel / 2, 0, 0})};
    return scene;
}

// Irradiance at floor point (x, 0, z), averaged over the shutter: int H^2 / r^4 over the
// light at each of 64 instants (the light moves linearly), by a midpoint rule.
double exact_irradiance(double x, double z) {
    const int n = 40, times = 64;
    double sum = 0;
    for (int t = 0; t < times; ++t) {
        const double cx = -kTravel / 2 + kTravel * (t + 0.5) / times;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const double lx = cx - kSide / 2 + kSide * (i + 0.5) / n;
                const double lz = -kSide / 2 + kSide * (j + 0.5) / n;
                const double dx = lx - x, dz = lz - z, r2 = dx * dx + dz * dz + kH * kH;
                sum += kH * kH / (r2 * r2);
            }
    }
    return sum * (kSide / n) * (kSide / n) / times;
}

struct ImageMean {
    double mean = 0, se = 0;
};

ImageMean render_mean(const Scene& scene, LightStrategy strategy) {
    const EmbreeAccel accel(scene);
    const LightSet lights(scene, nullptr);
    const RenderContext ctx{scene, accel, lights};
    // Straight down from between the floor and the light, so the light is not in view.
    const OrthographicCamera camera(Transform::look_at({0, 1, 0}, {0, 0, 0}, {0, 0, -1}),
                                    kHalfX, kHalfZ, kW, kHt);
    IntegratorOptions iopt;
    iopt.strategy = strategy;
    iopt.max_depth = 1;  // direct light only: the exact answer is the irradiance
    const auto integrator = make_integrator(IntegratorType::Path, iopt);
    RenderOptions opt;
    opt.spp = 256;
    opt.seed = 11;
    opt.progress = false;
    opt.filter = FilterType::Box;
    const Image img = render(ctx, camera, *integrator, opt).resolve();
    double sum = 0, sum2 = 0;
    for (int y = 0; y < kHt; ++y)
        for (int x = 0; x < kW; ++x) {
            const double v = img.at(x, y)[1];
            sum += v;
            sum2 += v * v;
        }
    const int n = kW * kHt;
    ImageMean m;
    m.mean = sum / n;
    // Pixels differ systematically (the irradiance falls off), so this spread bounds the
    // noise of the mean from above.
    m.se = std::sqrt(std::max(0.0, sum2 / n - m.mean * m.mean) / n);
    return m;
}

TEST(MovingEmitter, LightSamplingFollowsTheEmitterThroughTheShutter) {
    const Scene scene = sliding_light_scene();
    ASSERT_TRUE(scene.has_motion());
    double exact = 0;  // image mean of radiance 0.8 / pi * E, at pixel centres
    for (int y = 0; y < kHt; ++y)
        for (int x = 0; x < kW; ++x)
            exact += exact_irradiance(-kHalfX + 2 * kHalfX * (x + 0.5) / kW,
                                      -kHalfZ + 2 * kHalfZ * (y + 0.5) / kHt);
    exact *= 0.8 / kPi / (kW * kHt);
    const ImageMean light = render_mean(scene, LightStrategy::LightOnly);
    const ImageMean bsdf = render_mean(scene, LightStrategy::BsdfOnly);
    const ImageMean mis = render_mean(scene, LightStrategy::Mis);
    // The pixel-centre midpoint rule against box-filtered pixels: the irradiance is
    // smooth at the scale of a pixel (0.125), well under 0.5% apart.
    for (const auto& [name, m] : {std::pair{"light", light}, {"bsdf", bsdf}, {"mis", mis}})
        EXPECT_NEAR(m.mean, exact, 4 * m.se + 0.005 * exact) << name << " sampling";
    EXPECT_NEAR(light.mean, bsdf.mean, 4 * std::hypot(light.se, bsdf.se));
}

}  // namespace
}  // namespace penumbra
