// A camera for scenes that define none: it frames the whole scene from the front (+Z),
// slightly above, so every Khronos sample renders something recognisable. The framing
// (the bounding sphere and the distance that fits it in view) is shared with the orbit
// views (orbit_cameras.h).
#pragma once

#include "core/scene/scene.h"

namespace penumbra {

// The scene's bounding sphere and the distance from its centre at which a perspective
// camera of vertical field of view yfov (radians) and aspect width / height sees all of
// it, with a 10% margin; znear suits that distance.
struct Framing {
    Vec3 center;
    float radius = 1, distance = 1, znear = 0.01f;
};
Framing frame_bounds(const Bounds3& bounds, float yfov, float aspect);

// aspect: width / height of the image it will render.
CameraDesc default_camera(const Bounds3& bounds, float aspect);

}  // namespace penumbra
