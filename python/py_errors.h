// Python exceptions for the renderer's errors: penumbra.SceneError (a subclass of
// Exception) for bad scene, view and image files, named as the CLI prints them; bad option
// values are ValueError (py_options.h).
#pragma once

#include <pybind11/pybind11.h>

namespace penumbra::python {

void bind_errors(pybind11::module_& m);

}  // namespace penumbra::python
