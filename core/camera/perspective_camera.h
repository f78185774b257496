// Pinhole perspective projection (glTF "perspective"): looks down local -Z.
#pragma once

#include "core/camera/camera.h"

namespace penumbra {

class PerspectiveCamera final : public Camera {
public:
    PerspectiveCamera(const Transform& to_world, float yfov, int width, int height);
    Ray generate_ray(const CameraSample& s) const override;
    bool reads_lens() const override { return false; }  // a pinhole

private:
    Transform m_to_world;
    Vec3 m_origin;  // the pinhole in world space, the same for every ray
    float m_tan_half_y, m_tan_half_x;
};

}  // namespace penumbra
