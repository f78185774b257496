#include "core/camera/perspective_camera.h"

#include <gtest/gtest.h>

#include <cmath>

namespace penumbra {
namespace {

constexpr int kWidth = 320, kHeight = 200;
constexpr float kYfov = 0.9f;

class PerspectiveCameraTest : public ::testing::Test {
protected:
    const Vec3 eye{1, 2, 3};
    const Transform to_world = Transform::look_at(eye, {-2, 0.5f, -1}, {0, 1, 0});
    const PerspectiveCamera cam{to_world, kYfov, kWidth, kHeight};
    const Vec3 forward = normalize(to_world.vector({0, 0, -1}));
    const Vec3 up = normalize(to_world.vector({0, 1, 0}));
    const Vec3 right = normalize(to_world.vector({1, 0, 0}));

    Ray ray(float x, float y, float time = 0) const {
        return cam.generate_ray({{x, y}, {0.5f, 0.5f}, time});
    }
    float angle_to_axis(Vec3 d) const {
        return std::acos(std::clamp(dot(d, forward), -1.0f, 1.0f));
    }
};

TEST_F(PerspectiveCameraTest, CenterRayLooksDownTheViewAxis) {
    const Ray r = ray(kWidth / 2.0f, kHeight / 2.0f, 0.25f);
    EXPECT_NEAR(length(r.o - eye), 0, 1e-5f);
    EXPECT_NEAR(dot(r.d, forward), 1, 1e-6f);
    EXPECT_NEAR(dot(forward, normalize(Vec3(-2, 0.5f, -1) - eye)), 1, 1e-6f);
    EXPECT_EQ(r.time, 0.25f);
}

TEST_F(PerspectiveCameraTest, EdgesAndCornersMakeTheFieldOfView) {
    const float tan_y = std::tan(kYfov / 2), tan_x = tan_y * kWidth / kHeight;
    // Top and bottom centers: half the vertical field of view, up and down (raster y
    // runs down).
    const Ray top = ray(kWidth / 2.0f, 0), bottom = ray(kWidth / 2.0f, kHeight);
    EXPECT_NEAR(angle_to_axis(top.d), kYfov / 2, 1e-5f);
    EXPECT_NEAR(angle_to_axis(bottom.d), kYfov / 2, 1e-5f);
    EXPECT_GT(dot(top.d, up), 0.1f);
    EXPECT_LT(dot(bottom.d, up), -0.1f);
    EXPECT_NEAR(dot(top.d, right), 0, 1e-6f);
    // Left and right centers: the horizontal half angle follows the aspect ratio.
    const Ray left = ray(0, kHeight / 2.0f), rgt = ray(kWidth, kHeight / 2.0f);
    EXPECT_NEAR(angle_to_axis(rgt.d), std::atan(tan_x), 1e-5f);
    EXPECT_NEAR(angle_to_axis(left.d), std::atan(tan_x), 1e-5f);
    EXPECT_GT(dot(rgt.d, right), 0.1f);
    EXPECT_LT(dot(left.d, right), -0.1f);
    // Corners: the diagonal.
    const float diag = std::atan(std::hypot(tan_x, tan_y));
    for (Vec2 c : {Vec2(0, 0), Vec2(kWidth, 0), Vec2(0, kHeight), Vec2(kWidth, kHeight)}) {
        const Ray r = ray(c.x, c.y);
        EXPECT_NEAR(angle_to_axis(r.d), diag, 1e-5f) << c.x << " " << c.y;
        EXPECT_NEAR(length(r.d), 1, 1e-6f);
    }
    // The top-left corner is up and to the left.
    EXPECT_GT(dot(ray(0, 0).d, up), 0);
    EXPECT_LT(dot(ray(0, 0).d, right), 0);
}

TEST_F(PerspectiveCameraTest, EveryRayStartsAtTheEye) {
    for (Vec2 f : {Vec2(3.5f, 7.25f), Vec2(300, 10), Vec2(100, 199)}) {
        const Ray r = ray(f.x, f.y);
        EXPECT_NEAR(length(r.o - eye), 0, 1e-5f);
        EXPECT_NEAR(length(r.d), 1, 1e-6f);
        EXPECT_GT(dot(r.d, forward), 0);
    }
}

}  // namespace
}  // namespace penumbra
