#include "core/camera/stepped_camera.h"

#include <algorithm>
#include <cmath>

namespace penumbra {

SteppedCamera::SteppedCamera(std::vector<std::unique_ptr<Camera>> steps)
    : Camera(steps.front()->width(), steps.front()->height()), m_steps(std::move(steps)) {}

Ray SteppedCamera::generate_ray(const CameraSample& s) const {
    const float k = std::round(std::clamp(s.time, 0.0f, 1.0f) * float(m_steps.size() - 1));
    return m_steps[size_t(k)]->generate_ray(s);
}

}  // namespace penumbra
