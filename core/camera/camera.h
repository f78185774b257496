// Cameras turn a film position (raster pixels, origin top-left, y down), a lens sample
// and a time into a world-space ray.
#pragma once

#include <memory>

#include "core/math/transform.h"
#include "core/ray.h"
#include "core/scene/scene.h"

namespace penumbra {

struct CameraSample {
    Vec2 film;  // raster coordinates, [0, width) x [0, height)
    Vec2 lens;  // [0,1)^2
    float time = 0;  // [0,1)
};

class Camera {
public:
    virtual ~Camera() = default;
    // The returned direction is unit length.
    virtual Ray generate_ray(const CameraSample& s) const = 0;
    // Whether generate_ray reads CameraSample::lens: a pinhole's caller skips drawing it.
    virtual bool reads_lens() const { return true; }
    int width() const { return m_width; }
    int height() const { return m_height; }

protected:
    Camera(int width, int height) : m_width(width), m_height(height) {}
    int m_width, m_height;
};

// Builds the camera a CameraDesc describes for a width x height image. Perspective
// keeps the vertical field of view; orthographic keeps ymag and takes the width from
// the image aspect.
std::unique_ptr<Camera> make_camera(const CameraDesc& desc, int width, int height);

}  // namespace penumbra
