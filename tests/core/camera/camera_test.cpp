#include "core/camera/camera.h"

#include <gtest/gtest.h>

#include <cmath>

namespace penumbra {
namespace {

// The camera-space slope of a raster position's ray: (x / -z, y / -z).
Vec2 slope(const Camera& cam, const Transform& to_world, Vec2 film) {
    const Vec3 d = to_world.inverse().vector(cam.generate_ray({film, {0.5f, 0.5f}, 0}).d);
    return {d.x / -d.z, d.y / -d.z};
}

// A camera that says it does not read the lens sample (the render loop then skips
// drawing it) gives the same ray, bit for bit, whatever the lens sample; one with an
// aperture reads it. Moving cameras answer as the camera they move.
TEST(MakeCamera, OnlyCamerasWithALensReadTheLensSample) {
    CameraDesc pinhole, ortho, lens, moving;
    pinhole.to_world = Transform::look_at({0, 1, 5}, {0, 0, 0}, {0, 1, 0});
    ortho = pinhole;
    ortho.type = ProjectionType::Orthographic;
    lens = pinhole;
    lens.aperture_radius = 0.05f;
    lens.focus_distance = 5;
    moving = pinhole;
    moving.motion = {pinhole.to_world, Transform::translate({0.1f, 0, 0}) * pinhole.to_world};
    for (const CameraDesc* desc : {&pinhole, &ortho, &moving}) {
        const auto cam = make_camera(*desc, 64, 48);
        ASSERT_FALSE(cam->reads_lens());
        for (float time : {0.0f, 0.6f}) {
            const Ray a = cam->generate_ray({{10.5f, 20.25f}, {0.1f, 0.2f}, time});
            const Ray b = cam->generate_ray({{10.5f, 20.25f}, {0.9f, 0.7f}, time});
            for (int i = 0; i < 3; ++i) {
                EXPECT_EQ(a.o[i], b.o[i]);
                EXPECT_EQ(a.d[i], b.d[i]);
            }
        }
    }
    EXPECT_TRUE(make_camera(lens, 64, 48)->reads_lens());
    CameraDesc moving_lens = lens;
    moving_lens.motion = moving.motion;
    EXPECT_TRUE(make_camera(moving_lens, 64, 48)->reads_lens());
}

TEST(MakeCamera, PerspectiveKeepsYfovAndSquarePixels) {
    CameraDesc desc;
    desc.type = ProjectionType::Perspective;
    desc.yfov = 0.7f;
    desc.aspect_ratio = 1.0f;  // the file's aspect differs from the image's
    desc.to_world = Transform::look_at({0, 1, 5}, {0, 0, 0}, {0, 1, 0});
    for (Vec2 size : {Vec2(400, 100), Vec2(100, 300), Vec2(64, 64)}) {
        const int w = int(size.x), h = int(size.y);
        const auto cam = make_camera(desc, w, h);
        ASSERT_EQ(cam->width(), w);
        ASSERT_EQ(cam->height(), h);
        const float tan_y = slope(*cam, desc.to_world, {w / 2.0f, 0}).y;
        const float tan_x = slope(*cam, desc.to_world, {float(w), h / 2.0f}).x;
        EXPECT_NEAR(tan_y, std::tan(desc.yfov / 2), 1e-5f);
        // Square pixels: a pixel step spans the same slope horizontally and vertically.
        EXPECT_NEAR(2 * tan_x / w, 2 * tan_y / h, 1e-6f) << w << "x" << h;
    }
}

TEST(MakeCamera, OrthographicKeepsYmagAndSquarePixels) {
    CameraDesc desc;
    desc.type = ProjectionType::Orthographic;
    desc.xmag = 1;  // a 1:2 window for a 3:1 image
    desc.ymag = 2;
    const auto cam = make_camera(desc, 300, 100);
    const Vec3 tl = cam->generate_ray({{0, 0}, {0.5f, 0.5f}, 0}).o;
    const Vec3 br = cam->generate_ray({{300, 100}, {0.5f, 0.5f}, 0}).o;
    EXPECT_NEAR(tl.y - br.y, 2 * desc.ymag, 1e-5f);
    EXPECT_NEAR((br.x - tl.x) / 300, (tl.y - br.y) / 100, 1e-6f);
}

}  // namespace
}  // namespace penumbra
