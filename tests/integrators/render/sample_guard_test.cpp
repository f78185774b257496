// The sample guard of the render loop: an integrator that returns NaN or Inf for some
// camera samples. Those samples are counted (RenderStats::nonfinite_samples, which the
// CLI prints in its summary and writes as penumbra:nonfinite_samples) and never reach
// the image: pixels keep the mean of their finite samples.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <limits>

#include "core/accel/embree_accel.h"
#include "core/camera/orthographic_camera.h"
#include "integrators/render.h"

namespace penumbra {
namespace {

// 1 everywhere, NaN in the image's right third for half of the samples, +Inf in the
// left quarter for every sample.
class PoisonedIntegrator final : public Integrator {
public:
    Spectrum Li(const Ray& ray, const RenderContext&, Sampler& sampler) const override {
        const float u = sampler.get_1d();
        if (ray.o.x < -0.5f) {
            ++injected;
            return Spectrum(std::numeric_limits<float>::infinity(), 0, 0);
        }
        if (ray.o.x > 1 / 3.0f && u < 0.5f) {
            ++injected;
            return Spectrum(0, std::numeric_limits<float>::quiet_NaN(), 0);
        }
        return Spectrum(1);
    }
    mutable std::atomic<uint64_t> injected{0};
};

TEST(SampleGuard, InjectedNonFiniteSamplesAreCountedAndNeverWritten) {
    const Scene scene;
    const EmbreeAccel accel(scene);
    const LightSet lights(scene, nullptr);
    const RenderContext ctx{scene, accel, lights};
    const int res = 12;
    const OrthographicCamera camera(Transform::look_at({0, 0, 1}, {0, 0, 0}, {0, 1, 0}), 1, 1,
                                    res, res);
    PoisonedIntegrator integrator;
    RenderOptions opt;
    opt.spp = 8;
    opt.progress = false;
    opt.filter = FilterType::Box;
    RenderStats stats;
    const Image img = render(ctx, camera, integrator, opt, &stats).resolve();
    ASSERT_GT(integrator.injected.load(), 0u);
    EXPECT_EQ(stats.nonfinite_samples, integrator.injected.load());
    int black = 0;
    for (int y = 0; y < res; ++y)
        for (int x = 0; x < res; ++x) {
            const float* p = img.at(x, y);
            for (int c = 0; c < 4; ++c) ASSERT_TRUE(std::isfinite(p[c])) << x << "," << y;
            // Every finite sample is 1, so a pixel is 1 (some finite sample) or 0 (none).
            if (p[0] == 0) {
                ++black;
            } else {
                EXPECT_FLOAT_EQ(p[0], 1.0f) << x << "," << y;
                EXPECT_FLOAT_EQ(p[1], 1.0f) << x << "," << y;
            }
        }
    EXPECT_GT(black, 0);  // the all-Inf columns
}

}  // namespace
}  // namespace penumbra
