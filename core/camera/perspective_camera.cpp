#include "core/camera/perspective_camera.h"

#include <cmath>

namespace penumbra {

PerspectiveCamera::PerspectiveCamera(const Transform& to_world, float yfov, int width,
                                     int height)
    : Camera(width, height), m_to_world(to_world), m_origin(to_world.point(Vec3(0, 0, 0))) {
    m_tan_half_y = std::tan(0.5f * yfov);
    m_tan_half_x = m_tan_half_y * static_cast<float>(width) / static_cast<float>(height);
}

Ray PerspectiveCamera::generate_ray(const CameraSample& s) const {
    // Raster to normalized device coordinates in [-1, 1], y up.
    const float ndc_x = 2 * s.film.x / m_width - 1;
    const float ndc_y = 1 - 2 * s.film.y / m_height;
    const Vec3 d_cam(ndc_x * m_tan_half_x, ndc_y * m_tan_half_y, -1);
    Ray r;
    r.o = m_origin;
    r.d = normalize(m_to_world.vector(d_cam));
    r.time = s.time;
    // One pixel's angle at the image centre (Akenine-Moller et al. 2021, eq. 30).
    r.cone.spread = 2 * m_tan_half_y / m_height;
    return r;
}

}  // namespace penumbra
