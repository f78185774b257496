// Parallel projection (glTF "orthographic"): rays along local -Z from a
// 2 xmag x 2 ymag window.
#pragma once

#include "core/camera/camera.h"

namespace penumbra {

class OrthographicCamera final : public Camera {
public:
    OrthographicCamera(const Transform& to_world, float xmag, float ymag, int width,
                       int height);
    Ray generate_ray(const CameraSample& s) const override;
    bool reads_lens() const override { return false; }  // no lens

private:
    Transform m_to_world;
    float m_xmag, m_ymag;
};

}  // namespace penumbra
