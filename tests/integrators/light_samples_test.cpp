// The direct integrator's --light-samples N: N shadow rays to N different points of one
// light, stratified over it. Unbiased (the image matches the exact irradiance for any N),
// and the stratification pays: N stratified samples leave far less than 1/N of the
// variance of one.
#include <gtest/gtest.h>

#include <cmath>

#include "core/accel/embree_accel.h"
#include "core/camera/orthographic_camera.h"
#include "core/lights/light_set.h"
#include "integrators/render.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

constexpr float kH = 1;     // light height
constexpr float kSide = 1;  // light side
constexpr int kRes = 32;
constexpr float kHalf = 0.05f;  // a small patch: the irradiance is nearly constant on it

// Irradiance at (x, 0, z) from the square light centred over the origin.
double exact_irradiance(double x, double z) {
    const int n = 200;
    double sum = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double lx = -kSide / 2 + kSide * (i + 0.5) / n;
            const double lz = -kSide / 2 + kSide * (j + 0.5) / n;
            const double dx = lx - x, dz = lz - z, r2 = dx * dx + dz * dz + kH * kH;
            sum += kH * kH / (r2 * r2);
        }
    return sum * (kSide / n) * (kSide / n);
}

struct Residuals {
    double mean = 0;      // of (value - exact) / exact
    double variance = 0;  // of that, over the pixels
};

Residuals render_residuals(int light_samples, const LightSetOptions& light_options) {
    Scene scene;
    const int floor = test::add_lambertian(scene, Spectrum(0.8f));
    const int emitter = test::add_lambertian(scene, Spectrum(0.0f));
    scene.materials[emitter].emissive = Spectrum(1.0f);
    test::add_instance(scene,
                       test::add_quad_object(scene, {-5, 0, 5}, {5, 0, 5}, {5, 0, -5},
                                             {-5, 0, -5}, floor),
                       Transform());
    const float h = kSide / 2;
    test::add_instance(scene,
                       test::add_quad_object(scene, {-h, kH, -h}, {h, kH, -h}, {h, kH, h},
                                             {-h, kH, h}, emitter),
                       Transform());
    const EmbreeAccel accel(scene);
    const LightSet lights(scene, nullptr, light_options);
    const RenderContext ctx{scene, accel, lights};
    const OrthographicCamera camera(Transform::look_at({0, 0.5f, 0}, {0, 0, 0}, {0, 0, -1}),
                                    kHalf, kHalf, kRes, kRes);
    IntegratorOptions iopt;
    iopt.light_samples = light_samples;
    iopt.bsdf_samples = 0;
    const auto integrator = make_integrator(IntegratorType::Direct, iopt);
    RenderOptions opt;
    opt.spp = 1;
    opt.seed = 5;
    opt.progress = false;
    opt.filter = FilterType::Box;
    const Image img = render(ctx, camera, *integrator, opt).resolve();
    double sum = 0, sum2 = 0;
    for (int y = 0; y < kRes; ++y)
        for (int x = 0; x < kRes; ++x) {
            const double e = 0.8 / kPi *
                             exact_irradiance(-kHalf + 2 * kHalf * (x + 0.5) / kRes,
                                              -kHalf + 2 * kHalf * (y + 0.5) / kRes);
            const double r = (img.at(x, y)[1] - e) / e;
            sum += r;
            sum2 += r * r;
        }
    const int n = kRes * kRes;
    Residuals res;
    res.mean = sum / n;
    res.variance = std::max(0.0, sum2 / n - res.mean * res.mean);
    return res;
}

// By area, where the variance within the chosen triangle dominates (solid-angle sampling
// leaves mostly the choice between the quad's two triangles, which stratification over
// one light cannot reduce).
TEST(LightSamples, StratifiedOverTheLightAndUnbiased) {
    const LightSetOptions area{LightSamplerType::Power, TriangleSampling::Area};
    const Residuals one = render_residuals(1, area);
    const Residuals sixteen = render_residuals(16, area);
    const Residuals many = render_residuals(64, area);
    for (const auto& [n, r] : {std::pair{1, one}, {16, sixteen}, {64, many}})
        EXPECT_NEAR(r.mean, 0.0, 4 * std::sqrt(r.variance / (kRes * kRes)) + 1e-3)
            << n << " light samples";
    // Independent samples would give one.variance / 16; the Latin hypercube does much
    // better on this smooth integrand.
    EXPECT_LT(sixteen.variance, 0.5 * one.variance / 16)
        << "1 sample: " << one.variance << ", 16: " << sixteen.variance;
    EXPECT_LT(many.variance, sixteen.variance);
}

// The light BVH and cosine-warped spherical triangles: unbiased for any N, and one
// sample already has far less variance than one by area.
TEST(LightSamples, SolidAngleSamplingIsUnbiasedAndBeatsArea) {
    const Residuals area = render_residuals(1, {LightSamplerType::Power, TriangleSampling::Area});
    for (int n : {1, 16}) {
        const Residuals r =
            render_residuals(n, {LightSamplerType::Bvh, TriangleSampling::SolidAngle});
        EXPECT_NEAR(r.mean, 0.0, 4 * std::sqrt(r.variance / (kRes * kRes)) + 1e-3)
            << n << " light samples";
        if (n == 1) {
            EXPECT_LT(r.variance, 0.25 * area.variance) << r.variance << " vs " << area.variance;
        }
    }
}

}  // namespace
}  // namespace penumbra
