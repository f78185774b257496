#include "core/camera/autofocus.h"

#include "core/camera/perspective_camera.h"

namespace penumbra {

std::optional<float> focus_distance_at(const CameraDesc& camera, int width, int height,
                                       float x, float y, const Accel& accel) {
    const PerspectiveCamera pinhole(camera.to_world, camera.yfov, width, height);
    CameraSample s;
    s.film = {x, y};
    const Ray ray = pinhole.generate_ray(s);
    const std::optional<Hit> hit = accel.intersect(ray);
    if (!hit) return std::nullopt;
    // The focus plane is perpendicular to the view axis: use depth, not distance.
    const Vec3 axis = normalize(camera.to_world.vector(Vec3(0, 0, -1)));
    return hit->t * dot(ray.d, axis);
}

}  // namespace penumbra
