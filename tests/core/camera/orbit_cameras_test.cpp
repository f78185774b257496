#include "core/camera/orbit_cameras.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/camera/default_camera.h"

namespace penumbra {
namespace {

const Bounds3 kBounds{Vec3(-1, 0, -2), Vec3(3, 1, 0)};

Vec3 eye(const CameraDesc& c) { return c.to_world.point(Vec3(0, 0, 0)); }
Vec3 forward(const CameraDesc& c) { return normalize(c.to_world.vector(Vec3(0, 0, -1))); }

// Every view looks at the centre from the framing distance, at the elevation, 360 / N
// degrees apart from +Z towards +X, upright.
TEST(OrbitCameras, EvenlyAroundTheVerticalAxisLookingAtTheCentre) {
    OrbitSettings s;
    s.elevation = 30;
    const std::vector<CameraDesc> cams = orbit_cameras(kBounds, 1.5f, 8, s);
    ASSERT_EQ(cams.size(), 8u);
    const Framing f = frame_bounds(kBounds, 40 * kPi / 180, 1.5f);
    for (size_t i = 0; i < cams.size(); ++i) {
        const Vec3 d = eye(cams[i]) - f.center;
        EXPECT_NEAR(length(d), f.distance, 1e-4f * f.distance) << i;
        EXPECT_NEAR(std::asin(d.y / length(d)) * 180 / kPi, 30, 1e-3) << i;
        const double az = std::atan2(d.x, d.z) * 180 / kPi;
        EXPECT_NEAR(std::remainder(az - 45.0 * double(i), 360.0), 0, 1e-3) << i;
        EXPECT_NEAR(dot(forward(cams[i]), normalize(-d)), 1, 1e-6) << i;
        EXPECT_GT(cams[i].to_world.vector(Vec3(0, 1, 0)).y, 0) << i;  // not upside down
        EXPECT_NEAR(cams[i].yfov, 40 * kPi / 180, 1e-6);
        EXPECT_EQ(cams[i].name, view_name(i));
    }
}

TEST(OrbitCameras, DistanceAndFieldOfViewAreTheSettings) {
    OrbitSettings s;
    s.distance = 7;
    s.yfov = 25;
    for (const CameraDesc& c : orbit_cameras(kBounds, 1, 3, s)) {
        EXPECT_NEAR(length(eye(c) - kBounds.center()), 7, 1e-5);
        EXPECT_NEAR(c.yfov, 25 * kPi / 180, 1e-6);
    }
}

// The jitter moves views by at most its angle, the same for a seed, and a view's jitter
// does not depend on how many views there are.
TEST(OrbitCameras, JitterIsBoundedAndSeeded) {
    OrbitSettings s;
    s.jitter = 5;
    s.seed = 11;
    const auto a = orbit_cameras(kBounds, 1, 6, s), b = orbit_cameras(kBounds, 1, 6, s);
    OrbitSettings other = s;
    other.seed = 12;
    const auto c = orbit_cameras(kBounds, 1, 6, other);
    OrbitSettings still = s;
    still.jitter = 0;
    const auto plain = orbit_cameras(kBounds, 1, 6, still);
    const Vec3 centre = kBounds.center();
    bool moved = false;
    for (size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(eye(a[i]), eye(b[i]));
        EXPECT_FALSE(eye(a[i]) == eye(c[i]));
        const Vec3 u = normalize(eye(a[i]) - centre), v = normalize(eye(plain[i]) - centre);
        // Up to 5 degrees in azimuth and in elevation: at most about 7.1 degrees apart.
        EXPECT_LT(std::acos(std::min(1.0f, dot(u, v))) * 180 / kPi, 7.1f) << i;
        moved = moved || length(u - v) > 1e-3f;
    }
    EXPECT_TRUE(moved);
    const auto more = orbit_cameras(kBounds, 1, 12, s);
    EXPECT_EQ(eye(more[0]), eye(a[0]));
}

TEST(OrbitCameras, PlacedCamerasKeepTheirTransform) {
    const Transform t = Transform::look_at(Vec3(0, 2, 5), Vec3(0, 0, 0), Vec3(0, 1, 0));
    const CameraDesc c = placed_camera("side", t, 30, 2, kBounds);
    EXPECT_EQ(c.name, "side");
    EXPECT_EQ(c.to_world.matrix().m, t.matrix().m);
    EXPECT_NEAR(c.yfov, 30 * kPi / 180, 1e-6);
    EXPECT_EQ(c.aspect_ratio, 2);
    EXPECT_GT(c.znear, 0);
}

}  // namespace
}  // namespace penumbra
