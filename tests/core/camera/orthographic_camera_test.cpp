#include "core/camera/orthographic_camera.h"

#include <gtest/gtest.h>

namespace penumbra {
namespace {

TEST(OrthographicCamera, RaysAreParallelAndSpanTheWindow) {
    const float xmag = 2.5f, ymag = 1.25f;
    const Transform to_world = Transform::look_at({4, -1, 2}, {0, 0, 0}, {0, 0, 1});
    const OrthographicCamera cam(to_world, xmag, ymag, 200, 100);
    const Vec3 forward = normalize(to_world.vector({0, 0, -1}));
    const Transform to_camera = to_world.inverse();
    Vec3 lo(1e30f), hi(-1e30f);
    for (Vec2 f : {Vec2(0, 0), Vec2(200, 0), Vec2(0, 100), Vec2(200, 100), Vec2(100, 50),
                   Vec2(17.5f, 83.25f)}) {
        const Ray r = cam.generate_ray({f, {0.5f, 0.5f}, 0.5f});
        EXPECT_NEAR(dot(r.d, forward), 1, 1e-6f);
        EXPECT_NEAR(length(r.d), 1, 1e-6f);
        EXPECT_EQ(r.time, 0.5f);
        const Vec3 o = to_camera.point(r.o);
        EXPECT_NEAR(o.z, 0, 1e-5f);  // all in the camera's z = 0 plane
        lo = min(lo, o);
        hi = max(hi, o);
    }
    EXPECT_NEAR(lo.x, -xmag, 1e-5f);
    EXPECT_NEAR(hi.x, xmag, 1e-5f);
    EXPECT_NEAR(lo.y, -ymag, 1e-5f);
    EXPECT_NEAR(hi.y, ymag, 1e-5f);
    // Raster (0, 0) is the top-left corner.
    const Vec3 tl = to_camera.point(cam.generate_ray({{0, 0}, {0.5f, 0.5f}, 0}).o);
    EXPECT_NEAR(tl.x, -xmag, 1e-5f);
    EXPECT_NEAR(tl.y, ymag, 1e-5f);
}

}  // namespace
}  // namespace penumbra
