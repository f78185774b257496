// Back-face culling for camera rays: which face of a single-sided surface is its front
// (the glTF winding, turned over by a mirroring instance, whatever the shading normals
// say), the same answer from every accelerator, and autofocus through culled surfaces.
#include "core/camera/camera_culling.h"

#include <gtest/gtest.h>

#include <utility>

#include "core/accel/accel.h"
#include "core/camera/autofocus.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

// The square [-1, 1]^2 at z = 0, counter-clockwise seen from +z (its glTF front),
// placed by xf; `normals` replaces its vertex normals (+z) when not zero.
Scene square(bool double_sided, const Transform& xf, Vec3 normals = {}) {
    Scene scene;
    const int m = test::add_lambertian(scene, Spectrum(0.5f));
    scene.materials[size_t(m)].double_sided = double_sided;
    const uint32_t obj =
        test::add_quad_object(scene, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, m);
    if (!(normals == Vec3())) {
        for (Vec3& n : scene.meshes[scene.objects[obj].meshes[0]].normals) n = normals;
    }
    test::add_instance(scene, obj, xf);
    return scene;
}

// Whether every accelerator's hit of the ray from (0.2, 0.3, from_z) along z towards the
// square is culled; fails the test if they disagree or miss.
bool culled_from(const Scene& scene, float from_z) {
    Ray ray;
    ray.o = Vec3(0.2f, 0.3f, from_z);
    ray.d = Vec3(0, 0, from_z > 0 ? -1.0f : 1.0f);
    std::optional<bool> first;
    for (const AccelType type : all_accel_types()) {
        const std::string name = accel_type_name(type);
        const auto accel = make_accel(type, scene);
        const std::optional<Hit> hit = accel->intersect(ray);
        EXPECT_TRUE(hit.has_value()) << name;
        if (!hit) return false;
        const bool culled = camera_culls(scene, make_surface_point(scene, ray, *hit), ray.d);
        if (first)
            EXPECT_EQ(culled, *first) << name;
        else
            first = culled;
    }
    return first.value_or(false);
}

TEST(CameraCulling, CullsOnlyTheBackOfASingleSidedSurface) {
    const Scene single = square(false, Transform());
    EXPECT_FALSE(culled_from(single, 3));
    EXPECT_TRUE(culled_from(single, -3));
    const Scene both = square(true, Transform());
    EXPECT_FALSE(culled_from(both, 3));
    EXPECT_FALSE(culled_from(both, -3));
}

// glTF 2.0, 3.7.2.1: a node whose global transform has a negative determinant winds its
// front faces clockwise. Mirrored in z the square's world vertices are the ones above,
// in the same order (still counter-clockwise from +z), but its front now faces -z;
// mirrored in x its world winding is clockwise from +z, and its front still faces +z.
TEST(CameraCulling, AMirroringInstanceTurnsTheWindingOver) {
    const Scene mirrored_z = square(false, Transform::scale({1, 1, -1}));
    EXPECT_TRUE(culled_from(mirrored_z, 3));
    EXPECT_FALSE(culled_from(mirrored_z, -3));
    const Scene mirrored_x = square(false, Transform::scale({-1, 1, 1}));
    EXPECT_FALSE(culled_from(mirrored_x, 3));
    EXPECT_TRUE(culled_from(mirrored_x, -3));
}

// Viewers cull by winding; the shading normals only shade (here they face -z).
TEST(CameraCulling, FollowsTheWindingNotTheShadingNormals) {
    const Scene scene = square(false, Transform(), Vec3(0, 0, -1));
    EXPECT_FALSE(culled_from(scene, 3));
    EXPECT_TRUE(culled_from(scene, -3));
}

// Passing a culled surface moves the ray just beyond it, in the same direction.
TEST(CameraCulling, PassingMovesTheRayBeyondTheSurface) {
    const Scene scene = square(false, Transform());
    const auto accel = make_accel(AccelType::Embree, scene);
    Ray ray;
    ray.o = Vec3(0.2f, 0.3f, -3);
    ray.d = Vec3(0, 0, 1);
    const std::optional<Hit> hit = accel->intersect(ray);
    ASSERT_TRUE(hit);
    pass_culled(make_surface_point(scene, ray, *hit), ray);
    EXPECT_GT(ray.o.z, 0);
    EXPECT_LT(ray.o.z, 1e-5f);
    EXPECT_NEAR(ray.o.x, 0.2f, 1e-6f);
    EXPECT_NEAR(ray.o.y, 0.3f, 1e-6f);
    EXPECT_FALSE(accel->intersect(ray).has_value());
}

// A camera at the origin looking down -z; a square at z = -1 facing away from it (single-
// or double-sided), another at z = -3 facing it.
TEST(CameraCulling, AutofocusFocusesOnWhatTheCameraSees) {
    for (bool double_sided : {false, true}) {
        Scene scene;
        const int near = test::add_lambertian(scene, Spectrum(0.5f));
        scene.materials[size_t(near)].double_sided = double_sided;
        const int far = test::add_lambertian(scene, Spectrum(0.5f));
        test::add_instance(
            scene,
            test::add_quad_object(scene, {-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}, {1, -1, -1}, near),
            Transform());
        test::add_instance(
            scene,
            test::add_quad_object(scene, {-2, -2, -3}, {2, -2, -3}, {2, 2, -3}, {-2, 2, -3}, far),
            Transform());
        CameraDesc cam;
        for (const AccelType type : all_accel_types()) {
            const std::string name = accel_type_name(type);
            const auto accel = make_accel(type, scene);
            const std::optional<float> d = focus_distance_at(cam, 32, 32, 16, 16, scene, *accel);
            ASSERT_TRUE(d) << name;
            // The centre ray lies on the axis: the depth is the distance, to rounding.
            EXPECT_NEAR(*d, double_sided ? 1.0f : 3.0f, 1e-5f) << name;
        }
    }
}

}  // namespace
}  // namespace penumbra
