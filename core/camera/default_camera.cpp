#include "core/camera/default_camera.h"

#include <algorithm>
#include <cmath>

#include "core/math/portable_math.h"

namespace penumbra {

CameraDesc default_camera(const Bounds3& bounds, float aspect) {
    CameraDesc cam;
    cam.name = "default";
    cam.type = ProjectionType::Perspective;
    cam.yfov = 40.0f * kPi / 180.0f;
    cam.aspect_ratio = aspect;
    Vec3 center(0, 0, 0);
    float radius = 1;
    if (!bounds.empty()) {
        center = bounds.center();
        radius = std::max(0.5f * length(bounds.diagonal()), 1e-6f);
    }
    // Fit the bounding sphere in the narrower of the two fields of view, with a margin.
    const float half_fov = 0.5f * cam.yfov;
    const float half_fov_min = aspect >= 1 ? half_fov : std::atan(std::tan(half_fov) * aspect);
    const float dist = 1.1f * radius / portable_sin(half_fov_min);
    const Vec3 dir = normalize(Vec3(0.35f, 0.3f, 1.0f));  // from the front, a little up-right
    cam.to_world = Transform::look_at(center + dir * dist, center, Vec3(0, 1, 0));
    cam.znear = std::max(1e-4f, dist - radius) * 0.01f;
    return cam;
}

}  // namespace penumbra
