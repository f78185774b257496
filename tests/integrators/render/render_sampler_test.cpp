// The render loop with each sampler: the low-discrepancy samplers agree with independent
// sampling on a scene with edges, shadows and indirect light (unbiasedness in the loop,
// where the filter, lens and time dimensions are drawn before the path's).
#include <gtest/gtest.h>

#include <cmath>

#include "core/accel/embree_accel.h"
#include "core/camera/perspective_camera.h"
#include "core/lights/directional_light.h"
#include "integrators/render.h"
#include "support/statistics/estimate.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

// A cube on a Lambertian floor under a directional light at 50 degrees.
Scene cube_on_floor() {
    Scene scene;
    const int floor = test::add_lambertian(scene, Spectrum(0.5f));
    const float s = 100;
    test::add_instance(
        scene, test::add_quad_object(scene, {-s, 0, s}, {s, 0, s}, {s, 0, -s}, {-s, 0, -s}, floor),
        Transform());
    const int red = test::add_lambertian(scene, Spectrum(0.8f, 0.2f, 0.1f));
    test::add_instance(scene, test::add_cube_object(scene, red),
                       Transform::trs({0, 0.5f, 0}, Quat{0, 0.38f, 0, 0.92f}, {1, 1, 1}));
    const Vec3 travel(std::sin(0.87f), -std::cos(0.87f), 0.2f);
    scene.lights.push_back(std::make_unique<DirectionalLight>(normalize(travel), Spectrum(2), s));
    return scene;
}

// Per quadrant of the image, the mean luminance over seeds (independent replicates).
TEST(RenderSamplers, LowDiscrepancySamplersAgreeWithIndependentSampling) {
    const Scene scene = cube_on_floor();
    EmbreeAccel accel(scene);
    const LightSet lights(scene, nullptr);
    const RenderContext ctx{scene, accel, lights};
    const int w = 24, h = 18;
    const PerspectiveCamera camera(Transform::look_at({2, 3, 4}, {0, 0.3f, 0}, {0, 1, 0}), 0.7f, w,
                                   h);
    const auto integrator = make_integrator(IntegratorType::Path, {});
    auto quadrants = [&](SamplerType type) {
        std::vector<test::Estimate> q;
        for (int k = 0; k < 4; ++k)
            q.push_back(test::estimate(8, [&](uint64_t seed) {
                RenderOptions opt;
                opt.spp = 16;
                opt.seed = 100 + seed;
                opt.sampler = type;
                opt.filter = FilterType::Box;
                opt.progress = false;
                opt.threads = 1;
                const Image img = render(ctx, camera, *integrator, opt).resolve();
                double sum = 0;
                for (int y = (k / 2) * h / 2; y < (k / 2 + 1) * h / 2; ++y)
                    for (int x = (k % 2) * w / 2; x < (k % 2 + 1) * w / 2; ++x)
                        sum +=
                            luminance(Spectrum(img.at(x, y)[0], img.at(x, y)[1], img.at(x, y)[2]));
                return sum / (w * h / 4);
            }));
        return q;
    };
    const auto reference = quadrants(SamplerType::Independent);
    for (SamplerType type : {SamplerType::ZSobol, SamplerType::Sobol, SamplerType::TabledSobol}) {
        const auto q = quadrants(type);
        for (int k = 0; k < 4; ++k) {
            const double se = std::hypot(q[k].std_error, reference[k].std_error);
            // 4.5 standard errors over 8 comparisons; a 2% bias would stand out.
            EXPECT_LT(std::abs(q[k].mean - reference[k].mean), 4.5 * se)
                << "sampler " << int(type) << " quadrant " << k << ": " << q[k].mean << " +- "
                << q[k].std_error << " against " << reference[k].mean << " +- "
                << reference[k].std_error;
            EXPECT_LT(4.5 * se, 0.02 * reference[k].mean) << "quadrant " << k;
        }
    }
}

}  // namespace
}  // namespace penumbra
