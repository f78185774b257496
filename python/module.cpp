// `import penumbra`: the renderer from Python. Bindings only; the scene set-up, views,
// options and image conversion are the CLI's own code (python/scene_render.h).
#include <pybind11/pybind11.h>

#include "python/py_errors.h"
#include "python/py_options.h"
#include "python/py_scene.h"

PYBIND11_MODULE(penumbra, m) {
    m.doc() = R"(penumbra: a physically based CPU path tracer for glTF 2.0.

    scene = penumbra.load("asset.glb", width=256, height=256, views="orbit:8")
    for v in range(scene.view_count()):
        image = scene.render(view=v, spp=32, aov="depth,normal")
        rgb, depth = image["rgba"][..., :3], image["depth"]

Options are the CLI's (penumbra.options()); errors are penumbra.SceneError and ValueError.)";
    penumbra::python::bind_errors(m);
    penumbra::python::bind_options(m);
    penumbra::python::bind_scene(m);
}
