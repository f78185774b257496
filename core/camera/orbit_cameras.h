// Views around a scene for multi-view batches: N cameras evenly spaced in azimuth around
// the vertical axis (+Y, glTF's up) through the centre of the scene's bounds, all looking
// at that centre, and cameras placed explicitly (position and target, or a matrix).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/scene/scene.h"

namespace penumbra {

struct OrbitSettings {
    float elevation = 20;  // degrees above the horizontal plane through the centre
    float distance = 0;    // from the centre, world units; 0: framed as default_camera frames
    float yfov = 40;       // vertical field of view, degrees (also explicit views' default)
    float jitter = 0;      // each view's azimuth and elevation move by up to +-jitter degrees
    uint64_t seed = 0;     // the jitter's: the same seed gives the same cameras
};

// View i of count looks from azimuth 360 i / count degrees, turning from +Z (the default
// camera's side) towards +X, plus its jitter; elevations stay within +-89 degrees so the
// up direction is defined. Named "view_0000", "view_0001", ...
std::vector<CameraDesc> orbit_cameras(const Bounds3& bounds, float aspect, int count,
                                      const OrbitSettings& settings);

// An explicit camera: to_world maps local -Z to the viewing direction and +Y up (glTF's
// camera axes); yfov in degrees.
CameraDesc placed_camera(const std::string& name, const Transform& to_world, float yfov,
                         float aspect, const Bounds3& bounds);

// "view_0007": the name of view i when the views file gives none.
std::string view_name(size_t index);

}  // namespace penumbra
