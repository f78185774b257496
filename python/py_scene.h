// penumbra.load() and penumbra.Scene: a scene loaded once, rendered through any view with
// any options to numpy arrays, the GIL released while it renders.
#pragma once

#include <pybind11/pybind11.h>

namespace penumbra::python {

void bind_scene(pybind11::module_& m);

}  // namespace penumbra::python
