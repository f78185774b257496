#include "python/py_errors.h"

#include "core/error.h"

namespace py = pybind11;

namespace penumbra::python {

void bind_errors(py::module_& m) {
    // The CLI prints these and goes on with the next image; Python gets the same message.
    static py::exception<SceneError> scene_error(m, "SceneError", PyExc_Exception);
    scene_error.attr("__doc__") =
        "A scene, cameras or image file that cannot be used; the message names the file and "
        "the element, as the CLI prints it (\"a.gltf: meshes[3].primitives[0]: ...\").";
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const SceneError& e) {
            scene_error(e.what());
        }
    });
}

}  // namespace penumbra::python
