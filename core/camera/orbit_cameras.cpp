#include "core/camera/orbit_cameras.h"

#include <algorithm>
#include <cstdio>

#include "core/camera/default_camera.h"
#include "core/math/portable_math.h"
#include "core/sampling/rng.h"

namespace penumbra {

namespace {

constexpr float kDegrees = kPi / 180.0f;

CameraDesc perspective(const std::string& name, float yfov_degrees, float aspect) {
    CameraDesc cam;
    cam.name = name;
    cam.type = ProjectionType::Perspective;
    cam.yfov = yfov_degrees * kDegrees;
    cam.aspect_ratio = aspect;
    return cam;
}

}  // namespace

std::string view_name(size_t index) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "view_%04zu", index);
    return buf;
}

std::vector<CameraDesc> orbit_cameras(const Bounds3& bounds, float aspect, int count,
                                      const OrbitSettings& s) {
    std::vector<CameraDesc> cams;
    const Framing f = frame_bounds(bounds, s.yfov * kDegrees, aspect);
    const float distance = s.distance > 0 ? s.distance : f.distance;
    for (int i = 0; i < count; ++i) {
        // One stream per view: a view's jitter does not depend on how many there are.
        Rng rng(s.seed, uint64_t(i));
        const float ja = (2 * rng.next_float() - 1) * s.jitter;
        const float je = (2 * rng.next_float() - 1) * s.jitter;
        const float azimuth = (360.0f * float(i) / float(count) + ja) * kDegrees;
        const float elevation = std::clamp(s.elevation + je, -89.0f, 89.0f) * kDegrees;
        float sa, ca, se, ce;
        portable_sincos(azimuth, &sa, &ca);
        portable_sincos(elevation, &se, &ce);
        const Vec3 dir(ce * sa, se, ce * ca);
        CameraDesc cam = perspective(view_name(size_t(i)), s.yfov, aspect);
        cam.to_world = Transform::look_at(f.center + dir * distance, f.center, Vec3(0, 1, 0));
        cam.znear = std::max(1e-4f, distance - f.radius) * 0.01f;
        cams.push_back(cam);
    }
    return cams;
}

CameraDesc placed_camera(const std::string& name, const Transform& to_world, float yfov,
                         float aspect, const Bounds3& bounds) {
    CameraDesc cam = perspective(name, yfov, aspect);
    cam.to_world = to_world;
    const Framing f = frame_bounds(bounds, cam.yfov, aspect);
    const Vec3 eye = to_world.point(Vec3(0, 0, 0));
    cam.znear = std::max(1e-4f, length(eye - f.center) - f.radius) * 0.01f;
    return cam;
}

}  // namespace penumbra
