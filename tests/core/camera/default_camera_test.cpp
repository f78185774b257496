#include "core/camera/default_camera.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/camera/camera.h"

namespace penumbra {
namespace {

Bounds3 box(Vec3 lo, Vec3 hi) {
    Bounds3 b;
    b.expand(lo);
    b.expand(hi);
    return b;
}

TEST(DefaultCamera, SeesAllCornersOfTheBounds) {
    for (const Bounds3& b : {box({-1, -1, -1}, {1, 1, 1}), box({10, 0, -3}, {14, 0.1f, 30}),
                             box({-100, 5, 5}, {100, 6, 6}), box({0, 0, 0}, {1e-3f, 2e-3f, 1e-3f})})
        for (Vec2 size : {Vec2(640, 360), Vec2(200, 600), Vec2(256, 256)}) {
            const float aspect = size.x / size.y;
            const CameraDesc desc = default_camera(b, aspect);
            ASSERT_EQ(desc.type, ProjectionType::Perspective);
            EXPECT_GT(desc.znear, 0.0f);
            const Transform to_camera = desc.to_world.inverse();
            const float tan_y = std::tan(desc.yfov / 2), tan_x = tan_y * aspect;
            for (int c = 0; c < 8; ++c) {
                const Vec3 corner(c & 1 ? b.hi.x : b.lo.x, c & 2 ? b.hi.y : b.lo.y,
                                  c & 4 ? b.hi.z : b.lo.z);
                const Vec3 p = to_camera.point(corner);
                ASSERT_GT(-p.z, desc.znear) << "corner " << c << " behind the near plane";
                EXPECT_LT(std::abs(p.x / -p.z), tan_x) << "corner " << c << ", aspect " << aspect;
                EXPECT_LT(std::abs(p.y / -p.z), tan_y) << "corner " << c << ", aspect " << aspect;
            }
            // The same through the camera it builds: the bounds' center is the image center.
            const auto cam = make_camera(desc, int(size.x), int(size.y));
            const Ray r = cam->generate_ray({{size.x / 2, size.y / 2}, {0.5f, 0.5f}, 0});
            const Vec3 to_center = normalize(b.center() - r.o);
            EXPECT_NEAR(dot(r.d, to_center), 1, 1e-5f);
        }
}

TEST(DefaultCamera, EmptyBoundsGiveAFiniteCamera) {
    const CameraDesc desc = default_camera(Bounds3{}, 1.5f);
    EXPECT_TRUE(is_finite(desc.to_world.point({0, 0, 0})));
    EXPECT_TRUE(is_finite(desc.to_world.vector({0, 0, -1})));
}

}  // namespace
}  // namespace penumbra
