#include "core/camera/thin_lens_camera.h"

#include <cmath>

#include "core/sampling/warp.h"

namespace penumbra {

ThinLensCamera::ThinLensCamera(const Transform& to_world, float yfov, int width, int height,
                               float aperture_radius, float focus_distance, int blades,
                               float blade_rotation)
    : Camera(width, height),
      m_to_world(to_world),
      m_aperture(aperture_radius),
      m_focus(focus_distance),
      m_blades(blades),
      m_blade_rotation(blade_rotation) {
    m_tan_half_y = std::tan(0.5f * yfov);
    m_tan_half_x = m_tan_half_y * static_cast<float>(width) / static_cast<float>(height);
}

Ray ThinLensCamera::generate_ray(const CameraSample& s) const {
    const float ndc_x = 2 * s.film.x / m_width - 1;
    const float ndc_y = 1 - 2 * s.film.y / m_height;
    const Vec3 d_pinhole(ndc_x * m_tan_half_x, ndc_y * m_tan_half_y, -1);
    // The pinhole ray meets the focus plane (z = -focus) at d * focus.
    const Vec3 p_focus = d_pinhole * m_focus;
    const Vec2 lens =
        m_blades >= 3
            ? square_to_polygon(s.lens, m_blades, m_blade_rotation) *
                  (1 / std::sqrt(polygon_area(m_blades) / kPi))
            : square_to_concentric_disk(s.lens);
    // Polygons are scaled to the disk's area so an f-stop keeps its light-gathering area.
    const Vec3 p_lens(lens.x * m_aperture, lens.y * m_aperture, 0);
    Ray r;
    r.o = m_to_world.point(p_lens);
    r.d = normalize(m_to_world.vector(p_focus - p_lens));
    r.time = s.time;
    // The pinhole's pixel angle: defocus blur is not part of the texture footprint.
    r.cone.spread = 2 * m_tan_half_y / m_height;
    return r;
}

float ThinLensCamera::circle_of_confusion_pixels(float depth) const {
    const float pixels_per_unit = 0.5f * m_height / m_tan_half_y;
    return 2 * m_aperture * std::abs(1 / m_focus - 1 / depth) * pixels_per_unit;
}

float aperture_radius_from_fstop(float fstop, float yfov, float sensor_height_mm) {
    const float focal_mm = 0.5f * sensor_height_mm / std::tan(0.5f * yfov);
    return 0.5f * (focal_mm / fstop) / 1000.0f;
}

}  // namespace penumbra
