// Motion blur end to end: the path tracer's image of a moving emitter is the analytic
// coverage ramp, and a static scene's image does not depend on the samples' times.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "core/accel/accel.h"
#include "core/camera/orthographic_camera.h"
#include "core/lights/light_set.h"
#include "core/scene/motion.h"
#include "integrators/render.h"
#include "support/accel_scenes.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

Image render_with(const Scene& scene, AccelType type, const Camera& camera, uint32_t spp) {
    const auto accel = make_accel(type, scene);
    const LightSet lights(scene, nullptr);
    const RenderContext ctx{scene, *accel, lights};
    const auto integrator = make_integrator(IntegratorType::Path, {});
    RenderOptions opt;
    opt.spp = spp;
    opt.seed = 3;
    opt.progress = false;
    opt.filter = FilterType::Box;
    return render(ctx, camera, *integrator, opt).resolve();
}

// An emissive quad (radiance 1, black base, x in [0, 2]) that moves +4 in x over the
// shutter, seen by an orthographic camera over x in [-1, 7] (64 x 8 pixels of 0.125),
// on black. A point x is covered for the u with 4u <= x <= 4u + 2: the fraction
//   c(x) = clamp(x / 4, 0, 1) - clamp((x - 2) / 4, 0, 1),
// a ramp from 0 up to 0.5 over [0, 2], flat to 4, down to 0 at 6. A pixel (box filter)
// averages c over its width.
TEST(MotionBlur, MovingEmitterGivesTheAnalyticCoverageRamp) {
    Scene scene;
    const int mat = test::add_lambertian(scene, Spectrum(0.0f));
    scene.materials[mat].emissive = Spectrum(1.0f);
    const uint32_t quad =
        test::add_quad_object(scene, {0, -1, 0}, {2, -1, 0}, {2, 2, 0}, {0, 2, 0}, mat);
    const uint32_t i = test::add_instance(scene, quad, Transform());
    scene.instances[i].motion = {Transform(), Transform::translate(Vec3(4, 0, 0))};
    const int W = 64, H = 8;
    const uint32_t spp = 1024;
    const OrthographicCamera camera(Transform::translate(Vec3(3, 0.5f, 5)), 4, 0.5f, W, H);
    auto coverage = [](double x) {
        return std::clamp(x / 4, 0.0, 1.0) - std::clamp((x - 2) / 4, 0.0, 1.0);
    };
    for (AccelType type : {AccelType::Embree, AccelType::BvhSah, AccelType::Grid}) {
        const Image img = render_with(scene, type, camera, spp);
        for (int px = 0; px < W; ++px) {
            const double x0 = -1 + 0.125 * px;
            double expected = 0;  // the pixel's average coverage (midpoint rule, 1000 cells)
            for (int k = 0; k < 1000; ++k) expected += coverage(x0 + 0.125 * (k + 0.5) / 1000);
            expected /= 1000;
            double mean = 0;
            for (int y = 0; y < H; ++y) mean += img.at(px, y)[1];
            mean /= H;
            // Each sample is 0 or 1 (radiance 1, nothing else lit): the column mean of
            // N = 8 rows x 1024 samples has a standard deviation of at most
            // sqrt(p (1 - p) / N) (independent samples; stratification only lowers it).
            // 4.5 of those, plus 1e-6 for float sums; columns the quad never reaches
            // (p = 0) must be exactly 0.
            const double sigma = std::sqrt(expected * (1 - expected) / (H * double(spp)));
            EXPECT_NEAR(mean, expected, 4.5 * sigma + 1e-6)
                << accel_type_name(type) << " column " << px;
        }
    }
}

// Forces every camera sample's time: for a static scene the image must not change by a
// bit, whatever the time (nothing may read time on a static path).
class FixedTimeCamera final : public Camera {
public:
    FixedTimeCamera(const Camera& inner, float time)
        : Camera(inner.width(), inner.height()), m_inner(inner), m_time(time) {}
    Ray generate_ray(const CameraSample& s) const override {
        CameraSample t = s;
        t.time = m_time;
        return m_inner.generate_ray(t);
    }

private:
    const Camera& m_inner;
    float m_time;
};

TEST(MotionBlur, StaticSceneIsBitwiseIndependentOfSampleTimes) {
    const Scene& scene = test::cornell_box();
    ASSERT_FALSE(scene.has_motion());
    const auto camera = make_camera(scene.cameras.at(0), 24, 24);
    for (AccelType type : {AccelType::Embree, AccelType::BvhSah}) {
        const Image base = render_with(scene, type, *camera, 4);
        for (float t : {0.0f, 0.37f, 1.0f}) {
            const FixedTimeCamera fixed(*camera, t);
            const Image img = render_with(scene, type, fixed, 4);
            ASSERT_EQ(img.pixels.size(), base.pixels.size());
            EXPECT_EQ(std::memcmp(img.pixels.data(), base.pixels.data(),
                                  base.pixels.size() * sizeof(float)),
                      0)
                << accel_type_name(type) << " time " << t;
        }
    }
}

// A moving camera renders at each sample's time what a static camera placed by
// camera_transform_at would.
TEST(MotionBlur, MovingCameraRaysFollowTheInterpolatedTransform) {
    CameraDesc desc;
    desc.yfov = 0.7f;
    desc.motion = {Transform::translate(Vec3(0, 0, 5)),
                   Transform::translate(Vec3(2, 1, 5)) *
                       Transform::rotate(Quat{0, 0.3826834f, 0, 0.9238795f})};
    desc.to_world = desc.motion[0];
    const auto moving = make_camera(desc, 32, 32);
    for (float u : {0.0f, 0.3f, 0.5f, 1.0f}) {
        CameraDesc still = desc;
        still.motion.clear();
        still.to_world = camera_transform_at(desc, u);
        const auto fixed = make_camera(still, 32, 32);
        CameraSample s;
        s.film = {7.5f, 20.25f};
        s.time = u;
        const Ray a = moving->generate_ray(s), b = fixed->generate_ray(s);
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(a.o[k], b.o[k], 1e-5f) << u;
            EXPECT_NEAR(a.d[k], b.d[k], 1e-5f) << u;
        }
        EXPECT_EQ(a.time, u);
    }
    CameraSample s;
    s.film = {16, 16};
    s.time = 1;
    EXPECT_NEAR(moving->generate_ray(s).o.x, 2.0f, 1e-5f);
}

}  // namespace
}  // namespace penumbra
