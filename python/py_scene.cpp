#include "python/py_scene.h"

#include <pybind11/stl.h>

#include <csignal>
#include <memory>
#include <optional>

#include "apps/penumbra/interrupt.h"
#include "core/log.h"
#include "python/py_arrays.h"
#include "python/py_options.h"
#include "python/scene_render.h"

namespace py = pybind11;

namespace penumbra::python {

namespace {

// A loaded scene and the options it was loaded with; render() takes others over them.
struct PyScene {
    RenderCommandOptions options;
    std::shared_ptr<SceneRenderer> renderer;
};

// quiet (the module's default) keeps the loader's and the renderer's notes off stderr.
void apply_log_level(const RenderCommandOptions& o) {
    set_log_level(o.quiet ? LogLevel::Error : LogLevel::Info);
}

PyScene load(const std::string& path, const py::kwargs& kwargs) {
    PyScene scene;
    scene.options = options_with(module_defaults(), kwargs);
    apply_log_level(scene.options);
    const RenderCommandOptions o = scene.options;
    py::gil_scoped_release release;  // a big file loads for seconds
    scene.renderer = std::make_shared<SceneRenderer>(path, o);
    return scene;
}

bool on_main_thread() {
    const py::module_ threading = py::module_::import("threading");
    return threading.attr("current_thread")().is(threading.attr("main_thread")());
}

py::dict render(PyScene& scene, std::optional<int> view, const py::kwargs& kwargs) {
    const RenderCommandOptions o = options_with(scene.options, kwargs);
    apply_log_level(o);
    std::optional<RenderedImage> image;
    int signal_status = 0;
    {
        // Python's own handler only sets a flag that this thread, in C++, would not see
        // until the render ends: on the main thread, where signals arrive, the CLI's
        // handler counts them and the render stops after its current pass.
        std::optional<InterruptScope> interrupt;
        if (on_main_thread()) interrupt.emplace();
        // Other Python threads run while this one renders; the renderer serialises renders
        // of one scene itself.
        py::gil_scoped_release release;
        image.emplace(scene.renderer->render(o, view.value_or(-1),
                                             interrupt ? &interrupt->count() : nullptr));
        if (interrupt) signal_status = interrupt->exit_status();
    }
    if (signal_status != 0) {
        // The signal again, now that Python's handlers are back: Ctrl-C raises
        // KeyboardInterrupt (even after a render that finished), SIGTERM does what the
        // program asked for (by default, ends it).
        std::raise(signal_status - 128);
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    }
    if (image->interrupted) {
        PyErr_SetNone(PyExc_KeyboardInterrupt);
        throw py::error_already_set();
    }
    return to_python(*image);
}

constexpr const char* kLoadDoc = R"(Load a glTF file (.gltf or .glb) once, to render it many times.

Keyword arguments are render options, the CLI's and the job file's (penumbra.options()
lists them): job-file keys such as spp=32, width=256, views="orbit:8", aov="depth,normal",
env_color=[1, 1, 1]; values have the JSON types a job file gives them. They become the
scene's defaults; Scene.render() takes others over them.

Raises penumbra.SceneError for a file that cannot be loaded (the message names the file and
the element) and ValueError for a bad option (the message names it).)";

constexpr const char* kRenderDoc = R"(Render one image to numpy arrays, as `penumbra render` would.

view: which of the views (views="orbit:N" or a cameras JSON file) to render, from 0;
  None without views (the file's first camera, camera=..., or one framing the scene).
Keyword arguments: render options over the scene's (penumbra.options()). Options that only
  the render loop, the views or the outputs read (spp, seed, threads, aov, denoise,
  exposure, views, orbit_*) reuse the loaded scene; others (width, camera, lights, ...)
  set it up again, as a new command would.

Returns a dict: "rgba" (H, W, 4), the EXR's beauty (exposed, in the output colour space);
one array per AOV layer, named in lower case ("depth" (H, W), "normal" (H, W, 3),
"albedo", ...; --aov names them); "camera" (name, transform_matrix camera to world in
OpenGL axes as transforms.json writes it, yfov, fl_x, fl_y, cx, cy); "spp"; "seconds".
All float32, rows top down. The same options give bitwise the pixels of the CLI's EXR
(before --half rounds them). The GIL is released while rendering. On the main thread,
Ctrl-C stops the render after its current pass and raises KeyboardInterrupt.)";

}  // namespace

void bind_scene(py::module_& m) {
    py::class_<PyScene>(m, "Scene", "A glTF scene loaded once; render() draws it to arrays.")
        .def("render", &render, py::arg("view") = py::none(), kRenderDoc)
        .def(
            "view_count",
            [](PyScene& s, const py::kwargs& kwargs) {
                const RenderCommandOptions o = options_with(s.options, kwargs);
                py::gil_scoped_release release;
                return s.renderer->view_count(o);
            },
            "How many views the scene's views option (or the one given) makes; 0 without.")
        .def_property_readonly(
            "path", [](const PyScene& s) { return s.renderer->path(); }, "The file's path.")
        .def_property_readonly(
            "loads", [](const PyScene& s) { return s.renderer->loads(); },
            "How many times the file was loaded and set up: 1 until a render changes an "
            "option the set-up reads.")
        .def("__repr__", [](const PyScene& s) {
            return "<penumbra.Scene '" + s.renderer->path() + "'>";
        });
    m.def("load", &load, py::arg("path"), kLoadDoc);
}

}  // namespace penumbra::python
