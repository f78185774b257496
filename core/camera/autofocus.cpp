#include "core/camera/autofocus.h"

#include "core/camera/camera_culling.h"
#include "core/camera/perspective_camera.h"

namespace penumbra {

std::optional<float> focus_distance_at(const CameraDesc& camera, int width, int height, float x,
                                       float y, const Scene& scene, const Accel& accel) {
    const PerspectiveCamera pinhole(camera.to_world, camera.yfov, width, height);
    CameraSample s;
    s.film = {x, y};
    Ray ray = pinhole.generate_ray(s);
    float t_passed = 0;  // along the ray to the last culled surface, in units of |d|
    for (int layer = 0; layer <= 256; ++layer) {
        const std::optional<Hit> hit = accel.intersect(ray);
        if (!hit) return std::nullopt;
        const SurfacePoint sp = make_surface_point(scene, ray, *hit);
        if (camera_culls(scene, sp, ray.d)) {
            t_passed += hit->t;
            pass_culled(sp, ray);
            continue;
        }
        // The focus plane is perpendicular to the view axis: use depth, not distance.
        const Vec3 axis = normalize(camera.to_world.vector(Vec3(0, 0, -1)));
        return (t_passed + hit->t) * dot(ray.d, axis);
    }
    return std::nullopt;
}

}  // namespace penumbra
