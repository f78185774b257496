// A camera for scenes that define none: it frames the whole scene from the front (+Z),
// slightly above, so every Khronos sample renders something recognisable.
#pragma once

#include "core/scene/scene.h"

namespace penumbra {

// aspect: width / height of the image it will render.
CameraDesc default_camera(const Bounds3& bounds, float aspect);

}  // namespace penumbra
