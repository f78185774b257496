// Camera motion blur: the camera a CameraDesc describes, generated in its own frame and
// placed by its motion at the sample's time (motion.h, the interpolation the instances
// use).
#pragma once

#include <memory>
#include <vector>

#include "core/camera/camera.h"
#include "core/scene/motion.h"

namespace penumbra {

class MovingCamera final : public Camera {
public:
    // local: the camera with an identity to_world (rays in camera space).
    MovingCamera(std::unique_ptr<Camera> local, const std::vector<Transform>& steps);
    Ray generate_ray(const CameraSample& s) const override;
    bool reads_lens() const override { return m_local->reads_lens(); }

private:
    std::unique_ptr<Camera> m_local;
    std::vector<QuatDecomposition> m_steps;
};

}  // namespace penumbra
