// Autofocus: the focus distance that puts the surface seen through a pixel in focus.
#pragma once

#include <optional>

#include "core/accel/accel.h"
#include "core/scene/scene.h"

namespace penumbra {

// Depth along the view axis of the first surface behind raster point (x, y) of a
// width x height image (pinhole ray through the point) that the camera sees, passing the
// backs of single-sided surfaces as the integrators do (camera_culling.h); empty when the
// ray escapes.
std::optional<float> focus_distance_at(const CameraDesc& camera, int width, int height, float x,
                                       float y, const Scene& scene, const Accel& accel);

}  // namespace penumbra
