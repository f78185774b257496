// White furnace of the glTF material model: spheres sweeping metallic and roughness,
// white base colour, under a uniform environment with no other light. Energy
// conservation means no sphere may come out brighter than the background, and nothing
// may be NaN (the MetalRoughSpheres sample in furnace form).
#include <gtest/gtest.h>

#include "core/accel/embree_accel.h"
#include "core/camera/perspective_camera.h"
#include "integrators/render.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

TEST(Furnace, MetallicRoughnessSpheresNeverOutshineTheBackground) {
    const int n = 5;
    Scene scene;
    for (int row = 0; row < n; ++row)
        for (int col = 0; col < n; ++col) {
            MaterialDesc m;
            m.base_color = {1, 1, 1, 1};
            m.metallic = row / float(n - 1);
            m.roughness = col / float(n - 1);
            scene.materials.push_back(m);
            const uint32_t sphere =
                test::add_sphere_object(scene, static_cast<int>(scene.materials.size() - 1));
            test::add_instance(scene, sphere,
                               Transform::translate({2.5f * (col - 2), 2.5f * (2 - row), 0}) *
                                   Transform::scale(Vec3(1)));
        }
    const EmbreeAccel accel(scene);
    const float L_env = 1;
    const LightSet lights(scene, std::make_unique<EnvironmentLight>(Spectrum(L_env), 10.0f));
    const RenderContext ctx{scene, accel, lights};
    // Orthographic-like view from far away: each sphere covers a block of pixels.
    const int res = 100;
    const PerspectiveCamera camera(Transform::look_at({0, 0, 200}, {0, 0, 0}, {0, 1, 0}),
                                   2 * std::atan(6.5f / 200), res, res);
    IntegratorOptions iopt;
    iopt.max_depth = 64;
    const auto integrator = make_integrator("path", iopt);
    RenderOptions opt;
    opt.spp = 32;
    opt.progress = false;
    opt.filter = "box";
    RenderStats stats;
    const Image img = render(ctx, camera, *integrator, opt, &stats).resolve();
    EXPECT_EQ(stats.nonfinite_samples, 0u);

    // Mean and spread per sphere over the pixels well inside its disk.
    for (int row = 0; row < n; ++row)
        for (int col = 0; col < n; ++col) {
            const float cx = (col + 0.5f) * res / n, cy = (row + 0.5f) * res / n;
            const float r_px = 0.7f * res / (2.6f * n);
            double sum = 0, sum2 = 0;
            int count = 0;
            for (int y = 0; y < res; ++y)
                for (int x = 0; x < res; ++x) {
                    const float dx = x + 0.5f - cx, dy = y + 0.5f - cy;
                    if (dx * dx + dy * dy > r_px * r_px) continue;
                    const float v = img.at(x, y)[1];
                    ASSERT_TRUE(std::isfinite(v));
                    sum += v;
                    sum2 += double(v) * v;
                    ++count;
                }
            ASSERT_GT(count, 20);
            const double mean = sum / count;
            const double se = std::sqrt(std::max(0.0, sum2 / count - mean * mean) / count);
            EXPECT_LE(mean, L_env + 4 * se + 1e-4)
                << "metallic " << row / float(n - 1) << " roughness " << col / float(n - 1)
                << ": mean " << mean << " +- " << se;
            // A smooth white metal is a perfect mirror: exactly the background. (Rough
            // metals lose energy, as single-scattering microfacet models do: at alpha 1
            // and normal incidence GGX keeps only 1 - ln 2 = 0.31.)
            if (row == n - 1 && col == 0) EXPECT_NEAR(mean, L_env, 4 * se + 1e-4);
        }
}

}  // namespace
}  // namespace penumbra
