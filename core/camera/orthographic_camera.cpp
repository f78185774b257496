#include "core/camera/orthographic_camera.h"

namespace penumbra {

OrthographicCamera::OrthographicCamera(const Transform& to_world, float xmag, float ymag,
                                       int width, int height)
    : Camera(width, height), m_to_world(to_world), m_xmag(xmag), m_ymag(ymag) {}

Ray OrthographicCamera::generate_ray(const CameraSample& s) const {
    const float ndc_x = 2 * s.film.x / m_width - 1;
    const float ndc_y = 1 - 2 * s.film.y / m_height;
    Ray r;
    r.o = m_to_world.point(Vec3(ndc_x * m_xmag, ndc_y * m_ymag, 0));
    r.d = normalize(m_to_world.vector(Vec3(0, 0, -1)));
    r.time = s.time;
    r.cone.width = 2 * m_ymag / m_height;  // one pixel, at every distance
    return r;
}

}  // namespace penumbra
