// Depth of field with the thin-lens model (Cook et al. 1984; PBRT's PerspectiveCamera):
// rays start at a point on the aperture, a disk or a regular n-bladed polygon, and pass
// through the point where the pinhole ray meets the plane of focus. Points off that
// plane blur into the aperture's shape.
#pragma once

#include "core/camera/camera.h"

namespace penumbra {

class ThinLensCamera final : public Camera {
public:
    ThinLensCamera(const Transform& to_world, float yfov, int width, int height,
                   float aperture_radius, float focus_distance, int blades = 0,
                   float blade_rotation = 0);
    Ray generate_ray(const CameraSample& s) const override;

    // Diameter in pixels of the blur disk of a point at view depth z (thin lens):
    // 2 A |1/z_f - 1/z| times the pixels per unit of the image plane at distance 1.
    float circle_of_confusion_pixels(float depth) const;

private:
    Transform m_to_world;
    float m_tan_half_y, m_tan_half_x;
    float m_aperture, m_focus;
    int m_blades;
    float m_blade_rotation;
};

// Aperture radius of an f-stop N for a perspective camera: focal length f from the
// sensor height and the vertical field of view, aperture diameter f / N. Sensor in mm,
// result in scene units (metres).
float aperture_radius_from_fstop(float fstop, float yfov, float sensor_height_mm);

}  // namespace penumbra
