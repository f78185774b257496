#include "integrators/render.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/error.h"
#include "core/sampling/hash.h"
#include "integrators/first_hit.h"

namespace penumbra {

namespace {

bool abandon(const RenderOptions& o) {
    return o.interrupts && o.interrupts->load(std::memory_order_relaxed) >= 2;
}

}  // namespace

bool render_samples(const RenderContext& ctx, const Camera& camera,
                    const Integrator& integrator, const RenderOptions& options, Film& film,
                    uint32_t first, uint32_t last, ProgressReporter* progress) {
    const int w = camera.width(), h = camera.height();
    CHECK(film.width() == w && film.height() == h);
    const std::unique_ptr<Filter> filter = make_filter(options.filter);
    // Built for the whole budget: stratified and Sobol index their strata by the sample
    // index within [0, spp), whatever the pass.
    const std::unique_ptr<Sampler> prototype =
        make_sampler(options.sampler, std::max(options.spp, last), options.seed);

    const int ts = std::max(1, options.tile_size);
    const int row0 = std::clamp(options.row_begin, 0, h);
    const int row1 = options.row_end > 0 ? std::clamp(options.row_end, row0, h) : h;
    const int tiles_x = (w + ts - 1) / ts, tiles_y = (row1 - row0 + ts - 1) / ts;
    std::atomic<bool> abandoned{false};

    // AOVs get their own instantiation of the tile loop, so a render without them does
    // no AOV work per sample.
    const bool first_hit = film.aovs().needs_first_hit();
    auto render_tile = [&](int tile, auto with_aovs) {
        std::unique_ptr<Sampler> sampler = prototype->clone();
        const int x0 = (tile % tiles_x) * ts, y0 = row0 + (tile / tiles_x) * ts;
        const int x1 = std::min(x0 + ts, w), y1 = std::min(y0 + ts, row1);
        for (int y = y0; y < y1; ++y) {
            // A second Ctrl-C should not wait for the pass: check once per row.
            if (abandon(options)) {
                abandoned = true;
                return;
            }
            for (int x = x0; x < x1; ++x)
                for (uint32_t s = first; s < last; ++s) {
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
                    if constexpr (decltype(with_aovs)::value) {
                        const AovRecord aov =
                            first_hit ? first_hit_aovs(ray, ctx,
                                                       hash_values(options.seed, x, y, s))
                                      : AovRecord{};
                        film.add_sample(x, y, L, fs.weight, aov);
                    } else {
                        film.add_sample(x, y, L, fs.weight);
                    }
                }
        }
        if (progress) progress->update(uint64_t(x1 - x0) * (y1 - y0) * (last - first));
    };

    const int threads = options.threads > 0 ? options.threads
                                            : tbb::this_task_arena::max_concurrency();
    tbb::task_arena arena(threads);
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, tiles_x * tiles_y),
                          [&](const tbb::blocked_range<int>& r) {
                              for (int t = r.begin(); t != r.end(); ++t) {
                                  if (film.aovs().any())
                                      render_tile(t, std::true_type{});
                                  else
                                      render_tile(t, std::false_type{});
                              }
                          });
    });
    return !abandoned;
}

uint32_t next_pass_samples(uint32_t done, uint32_t budget, double elapsed, double time_limit,
                           double max_pass_seconds) {
    if (done >= budget) return 0;
    if (done == 0) return 1;
    uint32_t n = std::min(done, budget - done);
    const double per_spp = elapsed / done;
    if (per_spp <= 0) return n;
    const double fit_pass = std::floor(max_pass_seconds / per_spp);
    n = static_cast<uint32_t>(std::clamp(fit_pass, 1.0, double(n)));
    if (time_limit > 0) {
        const double fit_limit = std::floor((time_limit - elapsed) / per_spp);
        if (fit_limit < 1) return 0;
        n = static_cast<uint32_t>(std::min(double(n), fit_limit));
    }
    return n;
}

Film render(const RenderContext& ctx, const Camera& camera, const Integrator& integrator,
            const RenderOptions& options, RenderStats* stats) {
    const Accel& accel = ctx.accel;
    const int w = camera.width(), h = camera.height();
    Film film = options.resume ? *options.resume : Film(w, h, options.aovs);
    const uint32_t resumed = options.resume ? std::min(options.resume_spp, options.spp) : 0;
    const int rows = (options.row_end > 0 ? std::min(options.row_end, h) : h) -
                     std::clamp(options.row_begin, 0, h);
    const uint64_t rays_before = accel.rays_traced();
    ProgressReporter progress(options.label, uint64_t(w) * rows * (options.spp - resumed),
                              "samples", options.progress, options.batch);
    if (options.time_limit > 0) progress.set_time_limit(options.time_limit);

    const auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    RenderStats s;
    s.spp = resumed;
    double last_checkpoint = 0;
    // Passes are planned from this run's own pace: a resumed render starts with short
    // passes again, so an early interrupt is honoured soon.
    while (const uint32_t n = next_pass_samples(s.spp - resumed, options.spp - resumed,
                                                elapsed(), options.time_limit)) {
        if (options.interrupts && options.interrupts->load() >= 1) {
            s.interrupted = true;
            break;
        }
        if (!render_samples(ctx, camera, integrator, options, film, s.spp, s.spp + n,
                            &progress)) {
            s.interrupted = s.aborted = true;
            break;
        }
        s.spp += n;
        ++s.passes;
        // Between passes no thread traces, so summing the per-thread counters is safe.
        progress.set_rays(accel.rays_traced() - rays_before);
        if (options.checkpoint && s.spp < options.spp &&
            elapsed() - last_checkpoint >= options.checkpoint_interval) {
            options.checkpoint(film, s.spp);
            last_checkpoint = elapsed();
        }
    }
    if (options.interrupts && options.interrupts->load() >= 1 && s.spp < options.spp)
        s.interrupted = true;
    progress.done();

    s.seconds = elapsed();
    s.rays = accel.rays_traced() - rays_before;
    s.camera_samples = uint64_t(w) * rows * (s.spp - resumed);
    s.nonfinite_samples = film.nonfinite_samples();
    if (stats) *stats = s;
    return film;
}

}  // namespace penumbra
