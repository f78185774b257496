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
