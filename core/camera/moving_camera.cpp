#include "core/camera/moving_camera.h"

namespace penumbra {

MovingCamera::MovingCamera(std::unique_ptr<Camera> local, const std::vector<Transform>& steps)
    : Camera(local->width(), local->height()),
      m_local(std::move(local)),
      m_steps(decompose_steps(steps)) {}

Ray MovingCamera::generate_ray(const CameraSample& s) const {
    const Ray local = m_local->generate_ray(s);
    const Mat4 m = motion_matrix_at(m_steps, s.time);
    Ray r = local;
    for (int i = 0; i < 3; ++i) {
        r.o[i] = m(i, 0) * local.o.x + m(i, 1) * local.o.y + m(i, 2) * local.o.z + m(i, 3);
        r.d[i] = m(i, 0) * local.d.x + m(i, 1) * local.d.y + m(i, 2) * local.d.z;
    }
    // Unit directions as every camera returns them (the steps are rigid up to rounding).
    r.d = normalize(r.d);
    return r;
}

}  // namespace penumbra
