// One image of a loaded scene, as the CLI renders it, to plain buffers: the set-up kept
// while only the view and the render loop's options change, the images the EXR would hold
// (the exposed beauty in the output space and each AOV layer, converted as render_writer.h
// converts them), and the view's camera. No Python here: the bindings convert at the edge.
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "apps/penumbra/scene_setup.h"
#include "core/image.h"
#include "job/render_options.h"
#include "job/view_list.h"

namespace penumbra::python {

struct ImageLayer {
    std::string name;                   // the EXR layer's name ("Depth")
    std::vector<std::string> channels;  // its channels ("Z")
    Image image;
};

struct RenderedImage {
    Image rgba;                       // the EXR's R, G, B, A
    std::vector<ImageLayer> layers;   // the EXR's other layers, in its order
    CameraDesc camera;                // the view's, lens overrides applied
    uint32_t spp = 0;
    double seconds = 0;               // the render loop's
    bool interrupted = false;         // stopped early by RenderOptions::interrupts
};

class SceneRenderer {
public:
    // Loads and sets up path as the options say (the CLI's setup_scene). Throws SceneError.
    SceneRenderer(std::string path, const RenderCommandOptions& o);

    // Renders view `view` of o.views (-1: no views, the file's or the automatic camera).
    // Options the set-up reads (lights, camera, size, colour, ...) differ from the loaded
    // scene's: set up again first, as a new command would. Serialised per scene.
    // interrupts: as RenderOptions::interrupts (null: none); a render stopped by them has
    // stopped() set.
    RenderedImage render(const RenderCommandOptions& o, int view,
                         const std::atomic<int>* interrupts = nullptr);

    // How many views o.views gives for this scene (0 without views).
    size_t view_count(const RenderCommandOptions& o);
    // How many times the file was loaded and set up.
    size_t loads() const { return m_loads; }
    const std::string& path() const { return m_path; }

private:
    void prepare(const RenderCommandOptions& o);

    std::string m_path;
    std::mutex m_mutex;
    std::unique_ptr<SceneSetup> m_setup;
    std::string m_setup_key;  // the options the set-up was made with
    std::string m_views_key;  // the views spec and orbit settings m_setup->views follow
    size_t m_loads = 0;
};

}  // namespace penumbra::python
