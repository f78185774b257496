#include "integrators/render.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <new>
#include <type_traits>

#include "core/error.h"
#include "core/sampling/hash.h"
#include "integrators/adaptive_sampling.h"
#include "integrators/camera_coverage.h"
#include "integrators/denoise_guide.h"
#include "integrators/first_hit.h"

namespace penumbra {

namespace {

bool abandon(const RenderOptions& o) {
    return o.interrupts && o.interrupts->load(std::memory_order_relaxed) >= 2;
}

// Pixels go in blocks of 4 x 2. For an integrator that takes a traced first hit, a
// full block's camera rays of one sample index are traced as one packet: coherent
// rays cost Embree about a third as much each in a packet as one by one
// (docs/performance-traversal.md, "Embree packets and streams"). Each pixel keeps its samples
// in index order, and each lane its own sampler, so the image does not change.
constexpr int kBlockW = 4, kBlockH = 2, kLanes = kBlockW * kBlockH;

// Work items: tiles, split further (down to 4x4) until there are at least 32 per
// thread, so a small image or a pass of few samples (the first passes render 1, 1,
// 2 spp) still keeps every thread busy to the end of the pass; TBB steals the
// rest. The image does not depend on it: each pixel's samples stay in index order
// in one work item.
struct TileGrid {
    int row0, row1, size, tiles_x, tiles_y;
};

TileGrid plan_tiles(const RenderOptions& options, int w, int h, int threads) {
    TileGrid g;
    g.row0 = std::clamp(options.row_begin, 0, h);
    g.row1 = options.row_end > 0 ? std::clamp(options.row_end, g.row0, h) : h;
    int ts = std::max(1, options.tile_size);
    auto tile_count = [&](int size) {
        return ((w + size - 1) / size) * ((g.row1 - g.row0 + size - 1) / size);
    };
    while (ts > 4 && tile_count(ts) < 32 * threads) ts = std::max(4, ts / 2);
    g.size = ts;
    g.tiles_x = (w + ts - 1) / ts;
    g.tiles_y = (g.row1 - g.row0 + ts - 1) / ts;
    return g;
}

// What every tile of one pass reads.
struct Pass {
    const RenderContext& ctx;
    const Camera& camera;
    const Integrator& integrator;
    const RenderOptions& options;
    Film& film;
    const Filter& filter;
    // Built for the whole budget: stratified and Sobol index their strata by the sample
    // index within [0, spp), whatever the pass. With two halves (the error AOV, denoising),
    // even and odd sample indices are two independently seeded sample streams of half the
    // budget each (sample 2i is stream 0's i-th, 2i+1 stream 1's): the difference of two
    // independent randomised estimates is a valid error estimate for any sampler, where
    // the spread of one QMC pixel's samples is not (Owen 2013, ch. 17, "replicates").
    const std::unique_ptr<Sampler>* prototypes;
    bool halves, first_hit, guides, packets;
    bool coverage;  // a transparent background: the film's alpha (camera_coverage.h)
    // The scene's Cryptomatte hashes where the film has a Cryptomatte layer, else null.
    const CryptomatteHashes* hashes;
    uint32_t first, last;
    const std::vector<uint8_t>* active;
    TileGrid grid;
    ProgressReporter* progress;
    std::atomic<bool>& abandoned;
};

// The samplers of a tile: one per lane, and per half where the film splits them.
struct TileSamplers {
    std::unique_ptr<Sampler> samplers[2][kLanes];
    bool halves;
    TileSamplers(const Pass& pass, int lanes) : halves(pass.halves) {
        for (int i = 0; i < lanes; ++i) {
            samplers[0][i] = pass.prototypes[0]->clone();
            if (halves) samplers[1][i] = pass.prototypes[1]->clone();
        }
    }
    Sampler& for_sample(int lane, uint32_t s) {
        return halves ? *samplers[s & 1][lane] : *samplers[0][lane];
    }
};

// Sample s of pixel (x, y): its camera ray, constructed at `ray` (an existing Ray,
// whose storage it reuses), the sampler left after the camera's dimensions for the
// integrator. In place: a ray assigned from a returned one is copied with 16-byte
// loads of the camera's narrower stores just made, which wait for those stores at
// every sample.
inline void camera_ray(const Pass& pass, int x, int y, uint32_t s, Sampler& sampler,
                       FilterSample& fs, Ray* ray) {
    sampler.start_pixel_sample({x, y}, pass.halves ? s >> 1 : s);
    // Filter importance sampling: the offset follows the filter, so the sample
    // only contributes to this pixel (with weight 1: Filter::sample).
    fs = pass.filter.sample(sampler.get_pixel_2d());
    CameraSample cs;
    cs.film = {x + 0.5f + fs.offset.x, y + 0.5f + fs.offset.y};
    if (pass.camera.reads_lens())
        cs.lens = sampler.get_2d();
    else
        sampler.skip_2d();
    cs.time = sampler.get_1d();
    static_assert(std::is_trivially_destructible_v<Ray>, "reused without destruction");
    ::new (ray) Ray(pass.camera.generate_ray(cs));
    if (!pass.ctx.ray_cones) ray->cone = RayCone{};
}

// A sample's radiance to the film, with its AOVs where the film has any (kAovs: a
// separate instantiation, so that a render without them does no AOV work per sample).
// hit: the camera ray's closest hit where the packet traced it (nullptr: not traced);
// first: the integrator's first vertex, where it recorded one.
template <bool kAovs>
inline void add_sample(const Pass& pass, int x, int y, uint32_t s, const Ray& ray,
                       const Spectrum& L, const FilterSample& fs,
                       const std::optional<Hit>* hit = nullptr,
                       const FirstVertex* first = nullptr) {
    if constexpr (kAovs) {
        // The key seeds the AOVs' own coin flips: hashed only where something draws them
        // (the guides, or first-hit AOVs the integrator's first vertex does not give).
        const bool drawn =
            pass.guides || (pass.first_hit && !(first && first->valid) && !(hit && !*hit));
        const uint64_t key = drawn ? hash_values(pass.options.seed, x, y, s) : 0;
        AovRecord aov = pass.first_hit ? first_hit_aovs(ray, pass.ctx, key, hit, first, pass.hashes)
                                       : AovRecord{};
        if (pass.guides) aov.guide = denoise_guide(ray, pass.ctx, key, hit);
        // An opaque first vertex with no coin-flipped surface before it covers fully.
        if (pass.coverage)
            aov.coverage = first && first->valid ? 1 : camera_coverage(ray, pass.ctx, hit);
        aov.offset2 = fs.offset.x * fs.offset.x + fs.offset.y * fs.offset.y;
        aov.odd = (s & 1) != 0;
        pass.film.add_sample(x, y, L, fs.weight, aov);
    } else {
        pass.film.add_sample(x, y, L, fs.weight);
    }
}

// A full block's samples, each sample index's camera rays traced as one packet.
template <bool kAovs>
inline void render_packets(const Pass& pass, TileSamplers& samplers, const int xs[kLanes],
                           const int ys[kLanes]) {
    for (uint32_t s = pass.first; s < pass.last; ++s) {
        Ray rays[kLanes];
        FilterSample fs[kLanes];
        for (int i = 0; i < kLanes; ++i)
            camera_ray(pass, xs[i], ys[i], s, samplers.for_sample(i, s), fs[i], &rays[i]);
        std::optional<Hit> hits[kLanes];
        pass.ctx.accel.intersect8(rays, hits);
        for (int i = 0; i < kLanes; ++i) {
            // With first-hit AOVs or coverage, the integrator hands over its first vertex.
            FirstVertex first;
            FirstVertex* wanted = kAovs && (pass.first_hit || pass.coverage) ? &first : nullptr;
            const Spectrum L = pass.integrator.Li_from_hit(rays[i], hits[i], pass.ctx,
                                                           samplers.for_sample(i, s), wanted);
            add_sample<kAovs>(pass, xs[i], ys[i], s, rays[i], L, fs[i], &hits[i], wanted);
        }
    }
}

// A partial block (image edge, inactive pixels) or an integrator without first hits:
// one ray at a time.
template <bool kAovs>
inline void render_one_by_one(const Pass& pass, TileSamplers& samplers, const int xs[kLanes],
                              const int ys[kLanes], int n) {
    for (int i = 0; i < n; ++i)
        for (uint32_t s = pass.first; s < pass.last; ++s) {
            Sampler& sampler = samplers.for_sample(0, s);
            FilterSample fs;
            Ray ray;
            camera_ray(pass, xs[i], ys[i], s, sampler, fs, &ray);
            add_sample<kAovs>(pass, xs[i], ys[i], s, ray,
                              pass.integrator.Li(ray, pass.ctx, sampler), fs);
        }
}

template <bool kAovs>
void render_tile(const Pass& pass, int tile) {
    const int w = pass.camera.width(), ts = pass.grid.size;
    TileSamplers samplers(pass, pass.packets ? kLanes : 1);
    const int x0 = (tile % pass.grid.tiles_x) * ts,
              y0 = pass.grid.row0 + (tile / pass.grid.tiles_x) * ts;
    const int x1 = std::min(x0 + ts, w), y1 = std::min(y0 + ts, pass.grid.row1);
    uint64_t taken = 0;
    for (int by = y0; by < y1; by += kBlockH) {
        // A second Ctrl-C should not wait for the pass: check once per block row.
        if (abandon(pass.options)) {
            pass.abandoned = true;
            return;
        }
        for (int bx = x0; bx < x1; bx += kBlockW) {
            int xs[kLanes], ys[kLanes], n = 0;
            for (int y = by; y < std::min(by + kBlockH, y1); ++y)
                for (int x = bx; x < std::min(bx + kBlockW, x1); ++x)
                    if (!pass.active || (*pass.active)[size_t(y) * w + x]) {
                        xs[n] = x;
                        ys[n] = y;
                        ++n;
                    }
            taken += uint64_t(n) * (pass.last - pass.first);
            if (pass.packets && n == kLanes)
                render_packets<kAovs>(pass, samplers, xs, ys);
            else
                render_one_by_one<kAovs>(pass, samplers, xs, ys, n);
        }
    }
    if (pass.progress) pass.progress->update(taken);
}

}  // namespace

bool render_samples(const RenderContext& ctx, const Camera& camera, const Integrator& integrator,
                    const RenderOptions& options, Film& film, uint32_t first, uint32_t last,
                    ProgressReporter* progress, const std::vector<uint8_t>* active) {
    const int w = camera.width(), h = camera.height();
    CHECK(film.width() == w && film.height() == h);
    CHECK(!active || active->size() == size_t(w) * h);
    // Two halves: two independently seeded streams (Pass::prototypes).
    const bool halves = film.aovs().splits_halves();
    const uint32_t budget = std::max(options.spp, last);
    const std::unique_ptr<Sampler> prototypes[2] = {
        make_sampler(options.sampler, halves ? (budget + 1) / 2 : budget, options.seed),
        halves ? make_sampler(options.sampler, (budget + 1) / 2,
                              hash_values(options.seed, 0x68616c76657331ull))
               : nullptr};
    const int threads =
        options.threads > 0 ? options.threads : tbb::this_task_arena::max_concurrency();
    std::atomic<bool> abandoned{false};
    const bool crypto = film.aovs().has(Aov::CryptoObject) || film.aovs().has(Aov::CryptoMaterial);
    const std::optional<CryptomatteHashes> hashes =
        crypto ? std::optional<CryptomatteHashes>(ctx.scene) : std::nullopt;
    const Pass pass{ctx,
                    camera,
                    integrator,
                    options,
                    film,
                    shared_filter(options.filter),
                    prototypes,
                    halves,
                    film.aovs().needs_first_hit(),
                    film.aovs().has(Aov::Denoise),
                    integrator.uses_first_hit(),
                    film.aovs().has(Aov::Coverage),
                    hashes ? &*hashes : nullptr,
                    first,
                    last,
                    active,
                    plan_tiles(options, w, h, threads),
                    progress,
                    abandoned};
    const auto render_tiles = [&](int begin, int end) {
        for (int t = begin; t != end; ++t) {
            if (film.aovs().any())
                render_tile<true>(pass, t);
            else
                render_tile<false>(pass, t);
        }
    };
    const int tiles = pass.grid.tiles_x * pass.grid.tiles_y;
    // One thread: the tiles in order on this one, without the scheduler, which adds
    // nothing there but waits whose length (and instruction count: render_instructions.sh
    // compares counts) follows the machine's load. Tiles do not share pixels, so the
    // image is the same in any order.
    if (threads == 1) {
        render_tiles(0, tiles);
        return !abandoned;
    }
    auto run = [&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, tiles), [&](const tbb::blocked_range<int>& r) {
            render_tiles(r.begin(), r.end());
        });
    };
    // render() runs all its passes in one arena of this size: reuse it rather than
    // make a new one per pass, whose workers would have to join it again each time.
    if (tbb::this_task_arena::max_concurrency() == threads) {
        run();
    } else {
        tbb::task_arena arena(threads);
        arena.execute(run);
    }
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

namespace {

// Offers the film to options.checkpoint between passes, at most every
// checkpoint_interval seconds and never after the last pass.
struct CheckpointClock {
    const RenderOptions& options;
    double last = 0;
    void after_pass(const Film& film, uint32_t spp, double now) {
        if (options.checkpoint && spp < options.spp && now - last >= options.checkpoint_interval) {
            options.checkpoint(film, spp);
            last = now;
        }
    }
};

// Adaptive passes: min_spp samples, then adaptive_step more at a time, to the pixels
// still active after each; every pass is even and starts at an even index. A resumed
// film (s.spp > 0) was checkpointed between two such passes, and the active pixels are
// a function of the film, so the continuation takes the same passes.
void render_adaptive(const RenderContext& ctx, const Camera& camera, const Integrator& integrator,
                     const RenderOptions& options, Film& film, ProgressReporter& progress,
                     RenderStats& s, uint64_t rays_before, const std::function<double()>& elapsed) {
    const size_t pixels = size_t(film.width()) * film.height();
    std::vector<uint8_t> active(pixels, 1);
    size_t n_active = pixels;
    const uint32_t min_spp =
        std::min(options.spp, options.min_spp ? (options.min_spp + 1) & ~1u
                                              : adaptive_min_spp(options.target_error));
    if (s.spp >= min_spp) n_active = update_active_pixels(film, options.target_error, active);
    CheckpointClock clock{options};
    while (n_active > 0 && s.spp < options.spp) {
        const uint32_t n =
            std::min(options.spp - s.spp, s.spp == 0 ? min_spp : adaptive_step(s.spp));
        if (options.interrupts && options.interrupts->load() >= 1) {
            s.interrupted = true;
            break;
        }
        if (options.time_limit > 0 && s.camera_samples > 0) {
            const double per_sample = elapsed() / double(s.camera_samples);
            if (elapsed() + per_sample * double(n) * double(n_active) > options.time_limit) break;
        }
        if (!render_samples(ctx, camera, integrator, options, film, s.spp, s.spp + n, &progress,
                            &active)) {
            s.interrupted = s.aborted = true;
            break;
        }
        s.camera_samples += uint64_t(n) * n_active;
        s.spp += n;
        ++s.passes;
        progress.set_rays(ctx.accel.rays_traced() - rays_before);
        if (s.spp >= min_spp) n_active = update_active_pixels(film, options.target_error, active);
        if (n_active > 0) clock.after_pass(film, s.spp, elapsed());
    }
    s.active_pixels = n_active;
}

// The passes of render(): adaptive ones with a target error, else growing ones.
void render_passes(const RenderContext& ctx, const Camera& camera, const Integrator& integrator,
                   const RenderOptions& options, Film& film, ProgressReporter& progress,
                   RenderStats& s, uint64_t rays_before, const std::function<double()>& elapsed) {
    if (options.target_error > 0) {
        render_adaptive(ctx, camera, integrator, options, film, progress, s, rays_before, elapsed);
        return;
    }
    // Passes are planned from this run's own pace: a resumed render starts with short
    // passes again, so an early interrupt is honoured soon.
    const uint32_t resumed = s.spp;
    CheckpointClock clock{options};
    for (;;) {
        const uint32_t n = next_pass_samples(s.spp - resumed, options.spp - resumed, elapsed(),
                                             options.time_limit);
        if (n == 0) break;
        if (options.interrupts && options.interrupts->load() >= 1) {
            s.interrupted = true;
            break;
        }
        if (!render_samples(ctx, camera, integrator, options, film, s.spp, s.spp + n, &progress)) {
            s.interrupted = s.aborted = true;
            break;
        }
        s.spp += n;
        ++s.passes;
        // Between passes no thread traces, so summing the per-thread counters is safe.
        progress.set_rays(ctx.accel.rays_traced() - rays_before);
        clock.after_pass(film, s.spp, elapsed());
    }
}

}  // namespace

Film render(const RenderContext& ctx, const Camera& camera, const Integrator& integrator,
            const RenderOptions& options, RenderStats* stats) {
    const Accel& accel = ctx.accel;
    const int w = camera.width(), h = camera.height();
    AovSet aovs = options.aovs;
    if (options.target_error > 0) {
        aovs.add(Aov::Error);
        aovs.add(Aov::Samples);
    }
    Film film = options.resume ? *options.resume : Film(w, h, aovs);
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
    // One arena for every pass (render_samples runs in it when the size matches).
    tbb::task_arena arena(options.threads > 0 ? options.threads
                                              : tbb::this_task_arena::max_concurrency());
    arena.execute([&] {
        render_passes(ctx, camera, integrator, options, film, progress, s, rays_before, elapsed);
    });
    if (options.interrupts && options.interrupts->load() >= 1 && s.spp < options.spp)
        s.interrupted = true;
    progress.done();

    s.seconds = elapsed();
    s.rays = accel.rays_traced() - rays_before;
    if (options.target_error <= 0) s.camera_samples = uint64_t(w) * rows * (s.spp - resumed);
    s.nonfinite_samples = film.nonfinite_samples();
    if (stats) *stats = s;
    return film;
}

}  // namespace penumbra
