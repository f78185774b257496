#include "apps/penumbra/group_scene.h"

#include "core/error.h"

namespace penumbra {

SceneSetup& group_setup(const BatchJob& job, GroupScene& g) {
    if (g.group != job.group) {
        g.setup.reset();  // the previous group's scene goes before the next one loads
        g.error.clear();
        g.group = job.group;
    }
    if (!g.error.empty()) throw SceneError(g.error);
    if (!g.setup) {
        try {
            g.setup = setup_scene(job.options, job.scene);
        } catch (const std::exception& e) {
            g.error = e.what();
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
