#include "python/scene_render.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include "apps/penumbra/batch.h"
#include "apps/penumbra/denoise_step.h"
#include "core/error.h"
#include "integrators/render.h"
#include "io/image/render_writer.h"
#include "job/aov_list.h"
#include "job/option_table.h"

namespace penumbra::python {

namespace {

// Options read only by the render loop (render_options_for), the views (view_cameras), the
// written files or the progress output: changing these keeps the loaded scene. Every other
// option may change the set-up (the default lights follow the camera and the image's
// aspect), so an option missing here costs a reload, never a wrong image.
const std::set<std::string>& after_setup_options() {
    static const std::set<std::string> flags = {
        "spp", "seed", "threads", "sampler", "filter", "time-limit", "aov", "denoise",
        "target-error", "adaptive-min-spp", "exposure", "quiet", "views", "orbit-elevation",
        "orbit-distance", "orbit-fov", "orbit-jitter", "orbit-seed", "output", "out-dir",
        "name", "overwrite", "checkpoint-interval", "no-preview", "half", "compression",
        "reference", "timing-metadata", "display", "view", "look"};
    return flags;
}

// The options the set-up depends on, as text. Of --views only whether there are views
// counts: with views the set-up frames the automatic camera (setup_scene). Of --aov only
// whether it has motion vectors: the scene is loaded with its neighbouring frames then.
std::string setup_key(const RenderCommandOptions& o) {
    std::string key = o.views.empty() ? "views=0" : "views=1";
    key += parse_aovs(o.aovs).has(Aov::Vector) ? "\nvector=1" : "\nvector=0";
    for (const OptionDecl& d : render_option_table())
        if (d.get && !after_setup_options().count(d.flag)) key += "\n" + d.flag + "=" + d.get(o);
    return key;
}

std::string views_key(const RenderCommandOptions& o) {
    std::string key = o.views;
    for (const char* flag :
         {"orbit-elevation", "orbit-distance", "orbit-fov", "orbit-jitter", "orbit-seed"})
        key += "\n" + render_option(flag).get(o);
    return key;
}


// The beauty and layers write_render would write for this film (not denoised: none).
void collect_images(const Film& film, const DenoiseStep* denoised, const SceneSetup& s,
                    const RenderCommandOptions& o, RenderedImage& out) {
    Image resolved = film.resolve();
    if (denoised) {
        out.rgba = denoised_beauty(denoised->beauty, resolved, o.exposure, *s.color).output;
        // The film's own estimate, as the EXR's Noisy.R/G/B.
        const Image noisy = make_beauty(std::move(resolved), o.exposure, *s.color).output;
        Image rgb(noisy.width, noisy.height, 3);
        for (size_t p = 0; p < size_t(noisy.width) * noisy.height; ++p)
            for (size_t c = 0; c < 3; ++c) rgb.pixels[p * 3 + c] = noisy.pixels[p * 4 + c];
        out.layers.push_back({"Noisy", {"R", "G", "B"}, std::move(rgb)});
    } else {
        out.rgba = make_beauty(std::move(resolved), o.exposure, *s.color).output;
    }
    AovLayers aovs = aov_layers(film, *s.color, std::exp2(o.exposure));
    for (const ExrLayer& l : aovs.layers) out.layers.push_back({l.name, l.channels, *l.image});
}

// What spans options (a denoised render's samples, --fstop against --aperture-radius) is
// checked as for a job file; in Python that is a bad option, a ValueError.
void check_options(const RenderCommandOptions& o) {
    try {
        validate_options(o, "options");
    } catch (const SceneError& e) {
        throw std::invalid_argument(e.what());
    }
}

}  // namespace

SceneRenderer::SceneRenderer(std::string path, const RenderCommandOptions& o)
    : m_path(std::move(path)) {
    check_options(o);
    prepare(o);
}

void SceneRenderer::prepare(const RenderCommandOptions& o) {
    const std::string key = setup_key(o);
    if (!m_setup || key != m_setup_key) {
        m_setup.reset();  // the old scene goes before the new one loads
        m_setup_key.clear();
        m_views_key.clear();
        m_setup = setup_scene(o, m_path);
        m_setup_key = key;
        ++m_loads;
    }
    if (!o.views.empty() && views_key(o) != m_views_key) {
        // What group_setup does for a batch's group: every view's camera, once per scene.
        m_setup->views = view_cameras(read_views(o.views), m_setup->scene.bounds(),
                                      float(m_setup->width) / float(m_setup->height), o.orbit);
        m_views_key = views_key(o);
    }
}

size_t SceneRenderer::view_count(const RenderCommandOptions& o) {
    if (o.views.empty()) return 0;
    std::lock_guard<std::mutex> lock(m_mutex);
    prepare(o);
    return m_setup->views.size();
}

RenderedImage SceneRenderer::render(const RenderCommandOptions& o, int view,
                                    const std::atomic<int>* interrupts) {
    check_options(o);
    if (o.views.empty() && view >= 0)
        throw std::invalid_argument("view=" + std::to_string(view) +
                                    ": no views to choose from (give views='orbit:N' or a "
                                    "cameras file)");
    std::lock_guard<std::mutex> lock(m_mutex);
    prepare(o);
    SceneSetup& s = *m_setup;
    if (!o.views.empty()) {
        if (view < 0 || size_t(view) >= s.views.size())
            throw std::invalid_argument("view=" + std::to_string(view) + ": expected 0 to " +
                                        std::to_string(s.views.size() - 1) + " for views '" +
                                        o.views + "'");
        use_view(s, size_t(view), o);
    }
    RenderOptions ropt = render_options_for(o, m_path);
    ropt.interrupts = interrupts;
    RenderStats stats;
    const Film film = penumbra::render(s.context(), *s.camera, *s.integrator, ropt, &stats);
    RenderedImage out;
    // A partial image is not the one asked for: the caller raises instead.
    out.interrupted = stats.interrupted || stats.aborted;
    if (out.interrupted) return out;
    const std::unique_ptr<DenoiseStep> denoised =
        o.denoise && stats.spp >= kDenoiseMinSpp ? denoise_film(film, o.threads) : nullptr;
    collect_images(film, denoised.get(), s, o, out);
    out.camera = s.camera_desc;
    out.spp = stats.spp;
    out.seconds = stats.seconds;
    return out;
}

}  // namespace penumbra::python
