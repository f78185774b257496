// A rendered image to Python: numpy arrays of the EXR's beauty and layers, and the view's
// camera in the NeRF convention of transforms.json.
#pragma once

#include <pybind11/pybind11.h>

#include "python/scene_render.h"

namespace penumbra::python {

// {"rgba": (H, W, 4), "depth": (H, W), "normal": (H, W, 3), ... one key per EXR layer, its
//  name in lower case; "camera": {...}, "spp": n, "seconds": s}. float32, rows top down.
pybind11::dict to_python(const RenderedImage& image);

}  // namespace penumbra::python
