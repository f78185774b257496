// KHR_animation_pointer and KHR_node_visibility end to end: the pixels of an animated
// colour and an animated visibility at still times (exact) and averaged over a shutter
// (the time integral, within the noise of the sample count). The scene
// (support/animated_scene.h), seen from +Z: an unlit quad over [-1, 1]^2 whose base colour
// goes LINEAR from red (0 s) to blue (1 s), and in front of its left half a green one,
// shown (STEP) from 0 s and hidden from 0.5 s.
#include <gtest/gtest.h>

#include <cmath>

#include "core/accel/accel.h"
#include "core/camera/orthographic_camera.h"
#include "core/lights/light_set.h"
#include "integrators/render.h"
#include "io/gltf/gltf_loader.h"
#include "materials/material.h"
#include "support/animated_scene.h"

namespace penumbra {
namespace {

constexpr int kSize = 32;

// Mean RGB over the left (x < -1/16) or right (x > 1/16) half's pixels.
struct Halves {
    Vec3 left, right;
    double samples_per_half;
};

Halves render_halves(const std::string& path, double open, double close, uint32_t spp) {
    GltfLoadOptions options;
    options.shutter_open = open;
    options.shutter_close = close;
    const Scene scene = load_gltf(path, options);
    const auto accel = make_accel(AccelType::Embree, scene);
    const LightSet lights(scene, nullptr);
    const RenderContext ctx{scene, *accel, lights, scene_has_alpha(scene)};
    const auto integrator = make_integrator(IntegratorType::Path, {});
    RenderOptions opt;
    opt.spp = spp;
    opt.seed = 11;
    opt.progress = false;
    opt.filter = FilterType::Box;
    const OrthographicCamera camera(Transform::translate(Vec3(0, 0, 5)), 1, 1, kSize, kSize);
    const Image img = render(ctx, camera, *integrator, opt).resolve();
    Halves h{{0, 0, 0}, {0, 0, 0}, 0};
    int n = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize / 2 - 1; ++x) {
            for (int c = 0; c < 3; ++c) {
                h.left[c] += img.at(x, y)[c];
                h.right[c] += img.at(kSize - 1 - x, y)[c];
            }
            ++n;
        }
    h.left = h.left / float(n);
    h.right = h.right / float(n);
    h.samples_per_half = double(n) * spp;
    return h;
}

void expect_rgb(Vec3 got, Vec3 want, double tol, const std::string& what) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], tol) << what << " channel " << c;
}

TEST(AnimatedPropertiesRender, StillTimesShowTheKeyedValues) {
    const test::ScratchDir dir;
    const std::string path = test::animated_scene(dir);
    // Every sample sees the same unlit colour: exact up to float sums.
    Halves h = render_halves(path, 0.25, 0.25, 4);
    expect_rgb(h.right, {0.75f, 0, 0.25f}, 1e-5, "0.25 s, back quad");
    expect_rgb(h.left, {0, 1, 0}, 1e-5, "0.25 s, green quad shown");
    h = render_halves(path, 0.75, 0.75, 4);
    expect_rgb(h.right, {0.25f, 0, 0.75f}, 1e-5, "0.75 s, back quad");
    expect_rgb(h.left, {0.25f, 0, 0.75f}, 1e-5, "0.75 s, green quad hidden");
}

// Over the shutter [0, 1] s the right half averages the colour ramp, (0.5, 0, 0.5); the
// left half is green until 0.5 s and the ramp's second half after:
// 0.5 (0, 1, 0) + integral over [0.5, 1] of (1 - t, 0, t) = (0.125, 0.5, 0.375).
// Time steps taken nearest (the trapezoid rule) are exact for a linear ramp, and the
// visibility flips at its exact time, so only the sampling noise remains: a sample's
// channel lies in [0, 1] (standard deviation at most 0.5), and the tolerance is 5 standard
// errors of the half's mean: below 0.0078, the shift that taking the earlier step instead
// of the nearest (half a step, 1/128 of the ramp) would make.
TEST(AnimatedPropertiesRender, ShutterAveragesColourAndVisibilityOverTime) {
    const test::ScratchDir dir;
    const Halves h = render_halves(test::animated_scene(dir), 0, 1, 512);
    const double tol = 5 * 0.5 / std::sqrt(h.samples_per_half);
    EXPECT_LT(tol, 0.0055);
    expect_rgb(h.right, {0.5f, 0, 0.5f}, tol, "right half");
    expect_rgb(h.left, {0.125f, 0.5f, 0.375f}, tol, "left half");
}

}  // namespace
}  // namespace penumbra
