#include "apps/penumbra/group_scene.h"

#include "core/error.h"

namespace penumbra {

void end_group(GroupScene& g, bool source_done) {
    g.loaded.recycle(std::move(g.setup));
    if (source_done) {
        // Destroyed here, its accelerator before the file whose meshes that reads.
        SceneSource done = std::move(g.loaded);
        g.loaded = SceneSource();
    }
}

bool more_frames(const std::vector<BatchJob>& jobs, size_t i) {
    for (size_t j = i + 1; j < jobs.size() && jobs[j].source == jobs[i].source; ++j)
        if (jobs[j].group != jobs[i].group) return true;
    return false;
}

SceneSetup& group_setup(const BatchJob& job, GroupScene& g) {
    if (g.group != job.group || g.source != job.source) {
        // The previous group's scene goes before the next one is posed or loaded.
        end_group(g, g.source != job.source);
        if (g.source != job.source) {
            g.source = job.source;
            g.source_error.clear();
        }
        g.error.clear();
        g.group = job.group;
    }
    if (!g.source_error.empty()) throw SceneError(g.source_error);
    if (!g.error.empty()) throw SceneError(g.error);
    if (!g.setup) {
        try {
            g.loaded.more_frames = g.more_frames;
            g.setup = setup_scene(job.options, job.scene, g.loaded);
        } catch (const std::exception& e) {
            (g.loaded.asset ? g.error : g.source_error) = e.what();
            throw;
        }
        if (job.views)
            g.setup->views =
                view_cameras(*job.views, g.setup->scene.bounds(),
                             float(g.setup->width) / float(g.setup->height), job.options.orbit);
    }
    if (job.view >= 0) use_view(*g.setup, size_t(job.view), job.options);
    ++g.setup->images;
    return *g.setup;
}

}  // namespace penumbra
