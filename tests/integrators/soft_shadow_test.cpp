// Soft shadows from area lights: the penumbra behind a straight occluder edge has the
// width the geometry predicts. A square light of side a at height H, an opaque plate
// covering x < 0 at height h, a white ground at y = 0: seen from ground point x, the
// edge hides the light points lx < -x (H/h - 1). So the visible fraction goes from 0 to
// 1 as x crosses [-w/2, w/2] with w = a h / (H - h), nearly linearly for a light small
// against H. Rendered with `direct` (16 shadow rays per shading point, to different
// points of the light), and compared pixel by pixel with the exact irradiance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/accel/embree_accel.h"
#include "core/camera/orthographic_camera.h"
#include "integrators/render.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

constexpr float kH = 4;  // light height
constexpr float kh = 2;  // occluder height
constexpr int kWidth = 240, kHeight = 24;
constexpr float kHalfX = 1.5f, kHalfZ = 0.15f;  // the strip of ground imaged

// Irradiance (for Le = 1) at ground point (x, 0, z) from the visible part of the light
// [-a/2, a/2]^2 at height H: int cos cos / r^2 dA = int H^2 / r^4 dA over
// lx >= -x (H/h - 1), by a midpoint rule whose cells along x are clipped to the visible
// part (relative error below 1e-3 here). Unclipped, a cell that the edge cuts counted
// whole: at the umbra's end, where the visible strip is thinner than a cell, that
// overstated the irradiance by a third, which stratified sampling's noise had hidden.
double exact_irradiance(double a, double x, double z, bool occluded = true) {
    const int n = 120;
    const double lx_min = occluded ? -x * (kH / kh - 1) : -a;
    double sum = 0;
    for (int i = 0; i < n; ++i) {
        const double l0 = std::max(-a / 2 + a * i / n, lx_min), l1 = -a / 2 + a * (i + 1) / n;
        if (l0 >= l1) continue;
        const double lx = 0.5 * (l0 + l1);
        for (int j = 0; j < n; ++j) {
            const double lz = -a / 2 + a * (j + 0.5) / n;
            const double dx = lx - x, dz = lz - z, r2 = dx * dx + dz * dz + kH * kH;
            sum += (l1 - l0) * kH * kH / (r2 * r2);
        }
    }
    return sum * (a / n);
}

struct Profile {
    std::vector<double> x;        // world x of each pixel column
    std::vector<double> value;    // mean over the rows
    std::vector<double> se;       // standard error of that mean
};

Profile render_profile(float a) {
    Scene scene;
    const int white = test::add_lambertian(scene, Spectrum(0.8f));
    const int black = test::add_lambertian(scene, Spectrum(0));
    MaterialDesc emitter;
    emitter.base_color = {0, 0, 0, 1};
    emitter.metallic = 0;
    emitter.emissive = Spectrum(1);
    scene.materials.push_back(emitter);
    const int light = static_cast<int>(scene.materials.size() - 1);
    // Ground, facing up.
    test::add_instance(scene,
                       test::add_quad_object(scene, {-10, 0, 10}, {10, 0, 10}, {10, 0, -10},
                                             {-10, 0, -10}, white),
                       Transform());
    // Occluder over x < 0, black so nothing bounces off it.
    test::add_instance(scene,
                       test::add_quad_object(scene, {-10, kh, -10}, {0, kh, -10}, {0, kh, 10},
                                             {-10, kh, 10}, black),
                       Transform());
    // The light, facing down.
    test::add_instance(scene,
                       test::add_quad_object(scene, {-a / 2, kH, -a / 2}, {a / 2, kH, -a / 2},
                                             {a / 2, kH, a / 2}, {-a / 2, kH, a / 2}, light),
                       Transform());
    const EmbreeAccel accel(scene);
    const LightSet lights(scene, nullptr);
    const RenderContext ctx{scene, accel, lights};
    // Looking straight down from just below the occluder at the strip z in +-kHalfZ.
    const OrthographicCamera camera(Transform::look_at({0, 1, 0}, {0, 0, 0}, {0, 0, -1}),
                                    kHalfX, kHalfZ, kWidth, kHeight);
    IntegratorOptions iopt;
    iopt.light_samples = 16;
    iopt.bsdf_samples = 0;
    const auto integrator = make_integrator(IntegratorType::Direct, iopt);
    RenderOptions opt;
    opt.spp = 64;
    opt.progress = false;
    opt.filter = FilterType::Box;
    const Image img = render(ctx, camera, *integrator, opt).resolve();

    Profile p;
    for (int x = 0; x < kWidth; ++x) {
        CameraSample cs;
        cs.film = {x + 0.5f, kHeight / 2.0f};
        p.x.push_back(camera.generate_ray(cs).o.x);
        double sum = 0, sum2 = 0;
        for (int y = 0; y < kHeight; ++y) {
            const double v = img.at(x, y)[1];
            sum += v;
            sum2 += v * v;
        }
        const double mean = sum / kHeight;
        p.value.push_back(mean);
        p.se.push_back(std::sqrt(std::max(0.0, sum2 / kHeight - mean * mean) / kHeight));
    }
    return p;
}

// Where the profile, normalized by its fully lit end, first reaches `level`, with
// linear interpolation between columns; columns are searched from the umbra side.
double crossing(const std::vector<double>& x, const std::vector<double>& v, double full,
                double level) {
    const bool increasing_x = x.back() > x.front();
    const int n = static_cast<int>(x.size());
    for (int k = 1; k < n; ++k) {
        const int i0 = increasing_x ? k - 1 : n - k, i1 = increasing_x ? k : n - k - 1;
        const double v0 = v[i0] / full, v1 = v[i1] / full;
        if (v0 < level && v1 >= level) return x[i0] + (x[i1] - x[i0]) * (level - v0) / (v1 - v0);
    }
    return NAN;
}

TEST(SoftShadow, PenumbraWidthMatchesTheGeometry) {
    const double pixel = 2 * kHalfX / kWidth;
    double widths[2];
    int k = 0;
    for (float a : {0.25f, 1.0f}) {
        const Profile p = render_profile(a);
        ASSERT_TRUE(p.x.front() < -1 && p.x.back() > 1 || p.x.front() > 1 && p.x.back() < -1);
        std::vector<double> exact(p.x.size()), unoccluded(p.x.size());
        for (size_t i = 0; i < p.x.size(); ++i) {
            // Averaged over the imaged z range, as the rows are.
            double e = 0, u = 0;
            const int zs = 6;
            for (int r = 0; r < zs; ++r) {
                const double z = -kHalfZ + 2 * kHalfZ * (r + 0.5) / zs;
                e += exact_irradiance(a, p.x[i], z);
                u += exact_irradiance(a, p.x[i], z, false);
            }
            exact[i] = e / zs;
            unoccluded[i] = u / zs;
        }
        // Le = 1, albedo 0.8: radiance = 0.8 / pi * E.
        for (size_t i = 0; i < p.x.size(); ++i) {
            const double expected = 0.8 / kPi * exact[i];
            EXPECT_NEAR(p.value[i], expected, 5 * p.se[i] + 0.01 * expected + 1e-6)
                << "a " << a << " x " << p.x[i];
        }
        // The 10%-90% width against the geometric prediction: the full penumbra is
        // w = a h / (H - h), and a linear ramp spends 80% of it between 10% and 90%.
        // The ramp is of the visible fraction: the rendered value over what the
        // unoccluded light would give at the same x (which falls off with distance).
        std::vector<double> fraction(p.x.size());
        for (size_t i = 0; i < p.x.size(); ++i)
            fraction[i] = p.value[i] / (0.8 / kPi * unoccluded[i]);
        const double w = a * kh / (kH - kh);
        const double x10 = crossing(p.x, fraction, 1, 0.1), x90 = crossing(p.x, fraction, 1, 0.9);
        ASSERT_TRUE(std::isfinite(x10) && std::isfinite(x90)) << "a " << a;
        const double measured = std::abs(x90 - x10);
        EXPECT_NEAR(measured, 0.8 * w, 1.5 * pixel) << "light side " << a;
        // And centred on the edge's geometric shadow line x = 0.
        EXPECT_NEAR(0.5 * (x10 + x90), 0.0, 1.5 * pixel) << "light side " << a;
        widths[k++] = measured;
    }
    // Four times the light, four times the penumbra.
    EXPECT_NEAR(widths[1] / widths[0], 4.0, 0.4);
}

}  // namespace
}  // namespace penumbra
