// Depth of field: the thin-lens camera's rays, the circle of confusion measured on a
// rendered image, and sharpness at the plane of focus.
#include "core/camera/thin_lens_camera.h"

#include <gtest/gtest.h>

#include "core/accel/embree_accel.h"
#include "core/camera/perspective_camera.h"
#include "core/sampling/rng.h"
#include "integrators/render.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

TEST(ThinLensCamera, RaysThroughAPixelMeetAtTheFocusPlane) {
    const Transform xf = Transform::look_at({1, 2, 3}, {0, 0, 0}, {0, 1, 0});
    const ThinLensCamera cam(xf, 0.7f, 64, 48, 0.2f, 2.5f);
    const PerspectiveCamera pinhole(xf, 0.7f, 64, 48);
    Rng rng(3);
    for (int i = 0; i < 50; ++i) {
        CameraSample s;
        s.film = {rng.next_float() * 64, rng.next_float() * 48};
        const Ray p = pinhole.generate_ray(s);
        // The pinhole ray reaches the focus plane at view depth 2.5.
        const Vec3 axis = normalize(xf.vector({0, 0, -1}));
        const Vec3 focus = p.o + p.d * (2.5f / dot(p.d, axis));
        for (int k = 0; k < 5; ++k) {
            s.lens = {rng.next_float(), rng.next_float()};
            const Ray r = cam.generate_ray(s);
            EXPECT_NEAR(length(r.d), 1.0f, 1e-5f);
            // r passes through the same focus point...
            const Vec3 to_focus = focus - r.o;
            EXPECT_NEAR(length(cross(normalize(to_focus), r.d)), 0.0f, 1e-4f);
            // ...from a point on the aperture disk around the pinhole.
            EXPECT_LE(length(r.o - p.o), 0.2f + 1e-5f);
        }
    }
    // The lens centre gives the pinhole ray.
    CameraSample c;
    c.film = {10, 20};
    c.lens = {0.5f, 0.5f};
    const Ray a = cam.generate_ray(c), b = pinhole.generate_ray(c);
    EXPECT_NEAR(length(a.d - b.d), 0.0f, 1e-6f);
}

TEST(ThinLensCamera, FstopGivesFocalLengthOverN) {
    // A 50 mm lens on a 24 mm sensor: yfov = 2 atan(12 / 50). At f/2 the aperture
    // diameter is 25 mm.
    const float yfov = 2 * std::atan(12.0f / 50.0f);
    EXPECT_NEAR(aperture_radius_from_fstop(2.0f, yfov, 24.0f), 0.0125f, 1e-6f);
}

// Renders an emissive square at depth z (facing the camera, black elsewhere) and returns
// the intensity-weighted variance of x across the image, in pixels^2.
double blur_variance(float aperture, int blades, float z_focus, float z, float half_size,
                     int res, float yfov) {
    Scene scene;
    MaterialDesc m;
    m.base_color = {0, 0, 0, 1};
    m.metallic = 0;
    m.specular = 0;
    m.emissive = Spectrum(100);
    scene.materials.push_back(m);
    const float s = half_size;
    const uint32_t quad =
        test::add_quad_object(scene, {-s, -s, -z}, {s, -s, -z}, {s, s, -z}, {-s, s, -z}, 0);
    test::add_instance(scene, quad, Transform());
    const EmbreeAccel accel(scene);
    const LightSet lights(scene, nullptr);
    const RenderContext ctx{scene, accel, lights};
    const ThinLensCamera cam(Transform(), yfov, res, res, aperture, z_focus, blades);
    const auto integrator = make_integrator(IntegratorType::Basic, {});
    RenderOptions opt;
    opt.spp = 128;
    opt.filter = FilterType::Box;
    opt.progress = false;
    const Image img = render(ctx, cam, *integrator, opt).resolve();
    double w = 0, wx = 0, wx2 = 0;
    for (int y = 0; y < res; ++y)
        for (int x = 0; x < res; ++x) {
            const double v = img.at(x, y)[0];
            w += v;
            wx += v * (x + 0.5);
            wx2 += v * (x + 0.5) * (x + 0.5);
        }
    const double mean = wx / w;
    return wx2 / w - mean * mean;
}

TEST(ThinLensCamera, OutOfFocusPointBlursIntoTheCircleOfConfusion) {
    const int res = 64;
    const float yfov = 0.5f, z_focus = 2, z = 4, aperture = 0.3f, half = 0.04f;
    const ThinLensCamera cam(Transform(), yfov, res, res, aperture, z_focus);
    const float coc = cam.circle_of_confusion_pixels(z);
    ASSERT_GT(coc, 15.0f);  // a blur well above pixel size
    const double pixels_per_unit = 0.5 * res / std::tan(0.5 * yfov);
    const double w = 2 * half / z * pixels_per_unit;  // sharp width of the square
    // A uniform disk of radius R has Var(x) = R^2 / 4; the square adds w^2 / 12 and the
    // pixel grid (box filter) 1 / 12 (Sheppard's correction).
    const double var = blur_variance(aperture, 0, z_focus, z, half, res, yfov);
    const double measured = 2 * std::sqrt(4 * (var - w * w / 12 - 1.0 / 12));
    EXPECT_NEAR(measured, coc, 1.0) << "measured blur diameter " << measured << " px";
    // A point at the focus distance stays sharp: only the square and the pixels.
    const double var_focus = blur_variance(aperture, 0, z, z, half, res, yfov);
    EXPECT_NEAR(var_focus, w * w / 12 + 1.0 / 12, 0.1);
}

TEST(ThinLensCamera, PolygonalApertureHasTheDisksAreaAndSecondMoment) {
    // Ray origins over the aperture: a hexagon scaled to the disk's area pi R^2 has
    // second moment 5 a^2 / 24 = 0.2519 R^2 about any axis (a: its side), the disk 0.25 R^2.
    const float R = 0.3f;
    for (int blades : {0, 6}) {
        const ThinLensCamera cam(Transform(), 0.5f, 16, 16, R, 2.0f, blades);
        Rng rng(11);
        double sx = 0, sy = 0, sxx = 0, rmax = 0;
        const int n = 400000;
        for (int i = 0; i < n; ++i) {
            CameraSample s;
            s.film = {8, 8};
            s.lens = {rng.next_float(), rng.next_float()};
            const Vec3 o = cam.generate_ray(s).o;
            sx += o.x;
            sy += o.y;
            sxx += double(o.x) * o.x;
            rmax = std::max(rmax, double(length(o)));
        }
        const double expected = (blades == 6 ? 0.2519 : 0.25) * R * R;
        EXPECT_NEAR(sxx / n, expected, 0.003 * R * R) << blades << " blades";
        EXPECT_NEAR(sx / n, 0.0, 1e-3);
        EXPECT_NEAR(sy / n, 0.0, 1e-3);
        // A hexagon of area pi R^2 reaches out to its circumradius 1.0996 R.
        EXPECT_LE(rmax, (blades == 6 ? 1.0997 : 1.0) * R + 1e-5);
    }
}

TEST(ThinLensCamera, PolygonalApertureBlursByTheSameAmountInTheImage) {
    // Same blur as the disk up to the moment ratio 1.0077; each image estimate carries
    // about 3% noise at this sample count, so this guards the scale (an unnormalized
    // inscribed hexagon would give 0.83), while the test above checks the moment exactly.
    const int res = 64;
    const float yfov = 0.5f, z_focus = 2, z = 4, aperture = 0.3f, half = 0.04f;
    const double disk = blur_variance(aperture, 0, z_focus, z, half, res, yfov);
    const double hex = blur_variance(aperture, 6, z_focus, z, half, res, yfov);
    EXPECT_NEAR(hex / disk, 1.0077, 0.08);
}

}  // namespace
}  // namespace penumbra
