#include "integrators/render.h"

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>

#include "core/progress.h"

namespace penumbra {

Film render(const RenderContext& ctx, const Camera& camera, const Integrator& integrator,
            const RenderOptions& options, RenderStats* stats) {
    const Accel& accel = ctx.accel;
    const int w = camera.width(), h = camera.height();
    Film film(w, h);
    const std::unique_ptr<Filter> filter = make_filter(options.filter);
    const std::unique_ptr<Sampler> prototype =
        make_sampler(options.sampler, options.spp, options.seed);

    const int ts = std::max(1, options.tile_size);
    const int tiles_x = (w + ts - 1) / ts, tiles_y = (h + ts - 1) / ts;
    const uint64_t rays_before = accel.rays_traced();
    ProgressReporter progress(options.label, uint64_t(w) * h * options.spp, "samples",
                              options.progress);

    auto render_tile = [&](int tile) {
        std::unique_ptr<Sampler> sampler = prototype->clone();
        const int x0 = (tile % tiles_x) * ts, y0 = (tile / tiles_x) * ts;
        const int x1 = std::min(x0 + ts, w), y1 = std::min(y0 + ts, h);
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x)
                for (uint32_t s = 0; s < options.spp; ++s) {
                    sampler->start_pixel_sample({x, y}, s);
                    // Filter importance sampling: the offset follows the filter, so the
                    // sample only contributes to this pixel, with weight f/pdf.
                    const FilterSample fs = filter->sample(sampler->get_pixel_2d());
                    CameraSample cs;
                    cs.film = {x + 0.5f + fs.offset.x, y + 0.5f + fs.offset.y};
                    cs.lens = sampler->get_2d();
                    cs.time = sampler->get_1d();
                    const Ray ray = camera.generate_ray(cs);
                    const Spectrum L = integrator.Li(ray, ctx, *sampler);
                    film.add_sample(x, y, L, fs.weight);
                }
        progress.update(uint64_t(x1 - x0) * (y1 - y0) * options.spp);
    };

    const auto start = std::chrono::steady_clock::now();
    const int threads = options.threads > 0 ? options.threads
                                            : tbb::this_task_arena::max_concurrency();
    tbb::task_arena arena(threads);
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, tiles_x * tiles_y),
                          [&](const tbb::blocked_range<int>& r) {
                              for (int t = r.begin(); t != r.end(); ++t) render_tile(t);
                          });
    });
    progress.done();

    if (stats) {
        stats->seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        stats->rays = accel.rays_traced() - rays_before;
        stats->camera_samples = uint64_t(w) * h * options.spp;
        stats->nonfinite_samples = film.nonfinite_samples();
    }
    return film;
}

}  // namespace penumbra
