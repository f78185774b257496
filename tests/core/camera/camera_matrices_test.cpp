// worldToCamera and worldToNDC in OpenEXR's conventions: checked against the cameras'
// own rays, so a compositor reprojecting with the header lands on the right pixel.
#include "core/camera/camera_matrices.h"

#include <gtest/gtest.h>

#include "core/camera/camera.h"

namespace penumbra {
namespace {

Vec4 apply(const Mat4& m, Vec3 p) {
    Vec4 r;
    for (int i = 0; i < 4; ++i) r[i] = m(i, 0) * p.x + m(i, 1) * p.y + m(i, 2) * p.z + m(i, 3);
    return r;
}

CameraDesc camera(ProjectionType type) {
    CameraDesc d;
    d.type = type;
    d.yfov = 0.7f;
    d.ymag = 1.5f;
    d.znear = 0.1f;
    d.zfar = 100;
    d.to_world = Transform::look_at({1, 2, 6}, {0, 0.5f, 0}, {0, 1, 0});
    return d;
}

TEST(CameraMatrices, WorldToCameraIsLeftHandedLookingDownPlusZ) {
    const CameraDesc d = camera(ProjectionType::Perspective);
    const Mat4 m = world_to_camera_lh(d);
    const Vec4 eye = apply(m, {1, 2, 6});
    EXPECT_NEAR(eye.x, 0, 1e-5f);
    EXPECT_NEAR(eye.z, 0, 1e-5f);
    // The target is straight ahead at its distance; "up" is +Y.
    const Vec4 target = apply(m, {0, 0.5f, 0});
    EXPECT_NEAR(target.x, 0, 1e-5f);
    EXPECT_NEAR(target.y, 0, 1e-5f);
    EXPECT_NEAR(target.z, length(Vec3(1, 1.5f, 6)), 1e-5f);
    const Vec4 above = apply(m, Vec3(0, 0.5f, 0) + d.to_world.vector({0, 1, 0}));
    EXPECT_GT(above.y, 0.9f);
}

TEST(CameraMatrices, WorldToNdcPutsRayPointsOnTheirPixel) {
    for (ProjectionType type : {ProjectionType::Perspective, ProjectionType::Orthographic}) {
        const CameraDesc d = camera(type);
        const int w = 40, h = 25;
        const std::unique_ptr<Camera> cam = make_camera(d, w, h);
        const Mat4 m = world_to_ndc(d, w, h);
        for (Vec2 film : {Vec2(0.5f, 0.5f), Vec2(39.5f, 3.25f), Vec2(20, 12.5f), Vec2(7, 24)}) {
            CameraSample cs;
            cs.film = film;
            const Ray r = cam->generate_ray(cs);
            for (float t : {0.5f, 3.0f, 40.0f}) {
                const Vec4 q = apply(m, r.o + r.d * t);
                EXPECT_NEAR(q.x / q.w, film.x / w, 1e-5f);
                EXPECT_NEAR(q.y / q.w, film.y / h, 1e-5f);
                EXPECT_GT(q.z / q.w, 0);
                EXPECT_LT(q.z / q.w, 1);
            }
        }
    }
}

}  // namespace
}  // namespace penumbra
