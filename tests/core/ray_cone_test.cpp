// Ray cones: the cameras' pixel spread, the footprint a hit derives from the cone and the
// triangle's UV-to-world ratio, and how a bounce widens the cone.
#include "core/ray_cone.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/camera/camera.h"
#include "core/surface_point.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

// The quad [-1, 1]^2 at z = 0 facing +z, UVs over [0, 1]^2 (uv area / world area = 1/4),
// placed by `xf`.
Scene quad_scene(const Transform& xf) {
    Scene s;
    const int mat = test::add_lambertian(s, Spectrum(0.5f));
    const uint32_t q =
        test::add_quad_object(s, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, mat);
    test::add_instance(s, q, xf);
    return s;
}

SurfacePoint hit_quad(const Scene& s, const Ray& ray, float t) {
    Hit h;
    h.t = t;
    h.b1 = 0.25f;
    h.b2 = 0.25f;
    return make_surface_point(s, ray, h);
}

// Width at the hit = width + spread * distance; over |cos|; times sqrt(uv / world area).
TEST(RayCone, FootprintAtAHit) {
    const Scene s = quad_scene(Transform());
    Ray r;
    r.o = {0, 0, 5};
    r.d = {0, 0, -1};
    r.cone = {0.002f, 0.01f};
    const SurfacePoint sp = hit_quad(s, r, 5);
    EXPECT_NEAR(sp.cone_width, 0.052f, 1e-6f);
    EXPECT_NEAR(sp.uv_width[0], 0.052f * 0.5f, 1e-6f);
    EXPECT_EQ(sp.uv_width[1], 0);  // no second UV set
    // Oblique at cos 0.8, and a direction of length 2 (t in units of |d|): same distance.
    r.d = Vec3(0.6f, 0, -0.8f) * 2;
    const SurfacePoint oblique = hit_quad(s, r, 2.5f * 1.25f);
    EXPECT_NEAR(oblique.cone_width, 0.002f + 0.01f * 6.25f, 1e-6f);
    EXPECT_NEAR(oblique.uv_width[0], oblique.cone_width / 0.8f * 0.5f, 1e-5f);
    // The instance's scale enters the world area: 4x the area, half the UV width.
    const Scene big = quad_scene(Transform::scale({2, 2, 1}));
    r.d = {0, 0, -1};
    EXPECT_NEAR(hit_quad(big, r, 5).uv_width[0], 0.052f * 0.25f, 1e-6f);
    // No cone, no footprint: lookups read the finest level.
    r.cone = {};
    EXPECT_EQ(hit_quad(s, r, 5).uv_width[0], 0);
}

// A specular bounce keeps the spread; a sampled lobe adds 2 / sqrt(pi pdf), capped at
// pi; rays without a cone stay without one.
TEST(RayCone, BouncesWidenByTheLobe) {
    const RayCone in{0.0f, 0.001f};
    const RayCone mirror = bounce_cone(in, 0.05f, 1, true);
    EXPECT_EQ(mirror.width, 0.05f);
    EXPECT_EQ(mirror.spread, 0.001f);
    const RayCone glossy = bounce_cone(in, 0.05f, 400, false);
    EXPECT_NEAR(glossy.spread, 0.001f + 2 / std::sqrt(kPi * 400), 1e-6f);
    const RayCone diffuse = bounce_cone(in, 0.05f, 1 / kPi, false);
    EXPECT_NEAR(diffuse.spread, 2.001f, 1e-5f);
    EXPECT_LT(glossy.spread, diffuse.spread);
    EXPECT_EQ(bounce_cone(in, 0.05f, 1e-6f, false).spread, kPi);
    EXPECT_FALSE(bounce_cone(RayCone{}, 0, 1, false).active());
}

// Perspective: the spread is one pixel's angle at the centre (neighbouring pixels' rays
// are that far apart); orthographic: the width is one pixel, the spread 0.
TEST(RayCone, CamerasStartWithOnePixel) {
    CameraDesc desc;
    desc.yfov = 0.6f;
    const auto cam = make_camera(desc, 64, 48);
    CameraSample a, b;
    a.film = {32, 24};
    b.film = {32, 25};
    const Ray ra = cam->generate_ray(a), rb = cam->generate_ray(b);
    EXPECT_NEAR(ra.cone.spread, std::acos(dot(ra.d, rb.d)), 1e-4f);
    EXPECT_EQ(ra.cone.width, 0);
    desc.type = ProjectionType::Orthographic;
    desc.ymag = 3;
    const auto ortho = make_camera(desc, 64, 48);
    const Ray oa = ortho->generate_ray(a), ob = ortho->generate_ray(b);
    EXPECT_NEAR(oa.cone.width, length(oa.o - ob.o), 1e-5f);
    EXPECT_EQ(oa.cone.spread, 0);
}

}  // namespace
}  // namespace penumbra
