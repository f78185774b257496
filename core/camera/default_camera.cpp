#include "core/camera/default_camera.h"

#include <algorithm>
#include <cmath>

#include "core/math/portable_math.h"

namespace penumbra {

Framing frame_bounds(const Bounds3& bounds, float yfov, float aspect) {
    Framing f;
    f.center = Vec3(0, 0, 0);
    f.radius = 1;
    if (!bounds.empty()) {
        f.center = bounds.center();
        f.radius = std::max(0.5f * length(bounds.diagonal()), 1e-6f);
    }
    // Fit the bounding sphere in the narrower of the two fields of view, with a margin.
    const float half_fov = 0.5f * yfov;
    const float half_fov_min = aspect >= 1 ? half_fov : std::atan(std::tan(half_fov) * aspect);
    f.distance = 1.1f * f.radius / portable_sin(half_fov_min);
    f.znear = std::max(1e-4f, f.distance - f.radius) * 0.01f;
    return f;
}

CameraDesc default_camera(const Bounds3& bounds, float aspect) {
    CameraDesc cam;
    cam.name = "default";
    cam.type = ProjectionType::Perspective;
    cam.yfov = 40.0f * kPi / 180.0f;
    cam.aspect_ratio = aspect;
    const Framing f = frame_bounds(bounds, cam.yfov, aspect);
    const Vec3 dir = normalize(Vec3(0.35f, 0.3f, 1.0f));  // from the front, a little up-right
    cam.to_world = Transform::look_at(f.center + dir * f.distance, f.center, Vec3(0, 1, 0));
    cam.znear = f.znear;
    return cam;
}

}  // namespace penumbra
