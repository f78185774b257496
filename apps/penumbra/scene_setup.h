// Everything one image needs before the render loop: the scene loaded, its camera and
// image size resolved, default lights added, the accelerator, integrator and camera
// built. Shared by `render` and `converge`, with the command-line options that drive it.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "apps/penumbra/render_command.h"
#include "apps/penumbra/scene_source.h"
#include "core/accel/accel.h"
#include "core/camera/camera.h"
#include "core/lights/light_set.h"
#include "core/scene/scene.h"
#include "integrators/motion_vector.h"
#include "integrators/render.h"
#include "io/color/color.h"

namespace penumbra {

struct SceneSetup {
    std::string path;
    Scene scene;
    CameraDesc camera_desc;  // after lens overrides
    // Which of scene.cameras camera_desc is; -1 for a view or the automatic camera.
    int file_camera = -1;
    // The cameras that map motion vectors, for a scene loaded with frame neighbours
    // (Aov::Vector); set with the camera.
    std::optional<MotionVectorCameras> motion_cameras;
    // --views: every view's camera, before lens overrides (use_view applies them). The
    // default lights and the dark-view check follow the default camera, so every view
    // sees the scene lit alike.
    std::vector<CameraDesc> views;
    int width = 0, height = 0;
    std::unique_ptr<LightSet> lights;
    std::unique_ptr<Accel> accel;
    std::unique_ptr<Integrator> integrator;
    std::unique_ptr<Camera> camera;
    MaterialOptions materials;
    bool default_lights = false;  // the default key and fill lights were added
    size_t file_lights = 0;       // the file's punctual lights rendered (0 with --no-file-lights)
    // The colour pipeline (--ocio-config, --working-space, ...): the scene's colours
    // were converted into its working space at load; outputs go through it.
    std::unique_ptr<ColorPipeline> color;
    double load_seconds = 0, build_seconds = 0;
    size_t images = 0;  // images set up from this load so far (group_setup counts them)

    // Refers to this setup: keep it alive (and in place) while rendering.
    RenderContext context() const;
};

// Loads and prepares path as the options say. Throws SceneError for bad input. The
// result refers to itself, hence the pointer.
std::unique_ptr<SceneSetup> setup_scene(const RenderCommandOptions& o, const std::string& path);
// The same, posing the source's file at the options' shutter: the file as loaded for
// earlier images whose options differ from o in their timing only (with their accelerator
// where nothing moved since), or loaded here (with o's load and colour options) and kept
// in `source` for the next images, which SceneSource::recycle hands the setup back to.
std::unique_ptr<SceneSetup> setup_scene(const RenderCommandOptions& o, const std::string& path,
                                        SceneSource& source);

// Renders the next image through view `index` of setup.views: its lens overrides
// applied and its camera built; the scene, lights and accelerator stay as they are.
void use_view(SceneSetup& setup, size_t index, const RenderCommandOptions& o);

// The render-loop options (samples, seed, sampler, filter, time, limits) from o.
RenderOptions render_options_for(const RenderCommandOptions& o, const std::string& label);

}  // namespace penumbra
