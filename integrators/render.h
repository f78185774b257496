// The render loop, in one place: the image is cut into tiles that TBB renders in
// parallel; every pixel sample seeds its sampler from (seed, pixel, sample index), so
// the image is bitwise identical for any thread count and any split into passes.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/camera/camera.h"
#include "core/film/film.h"
#include "core/film/filter.h"
#include "core/progress.h"
#include "core/sampling/sampler.h"
#include "integrators/integrator.h"

namespace penumbra {

struct RenderOptions {
    // The sample budget per pixel. Stratified and Sobol samplers lay their strata out
    // for this count, so a render stopped early has an unbiased, less even subset.
    uint32_t spp = 16;
    uint64_t seed = 0;
    int threads = 0;  // 0: all hardware threads
    int tile_size = 16;
    SamplerType sampler = SamplerType::TabledSobol;
    FilterType filter = FilterType::Gaussian;
    bool progress = true;
    std::string label = "render";
    // Scene time in seconds of the shutter's opening, for the record: the loader has
    // already posed the scene at it (io/gltf/gltf_loader.h), and the render loop does not read it.
    double time = 0;
    // Seconds for the whole image, 0: none. No pass starts that is predicted to end
    // after it; the first pass (1 spp) always runs.
    double time_limit = 0;
    // User interrupts so far (Ctrl-C): 1 stops after the current pass, 2 abandons the
    // pass at once. Written by a signal handler; polled here. nullptr: none.
    const std::atomic<int>* interrupts = nullptr;
    BatchProgress* batch = nullptr;  // the overall bar of a batch, or nullptr
    // AOVs to accumulate besides the beauty (the film render() returns has them). The
    // first-hit ones cost one more camera ray per sample, Aov::Denoise's guides one or
    // more, Aov::Coverage (a transparent background's alpha) one outside camera packets
    // and one per surface it passes; rays traced include them.
    AovSet aovs;
    // Adaptive sampling (integrators/adaptive_sampling.h): > 0 stops each pixel once its
    // estimated relative standard error is below this, after at least min_spp samples
    // (0: adaptive_min_spp's rule) and at most spp. Adds the error and samples AOVs.
    double target_error = 0;
    uint32_t min_spp = 0;
    // Only rows [row_begin, row_end) are rendered (a farm band); row_end 0: to the last.
    // With filter importance sampling a sample only touches its own pixel, so a band's
    // rows equal those of the whole image bit for bit.
    int row_begin = 0, row_end = 0;
    // Continue a render: `resume` holds samples [0, resume_spp) of every pixel (a
    // checkpoint), and render() adds [resume_spp, spp).
    const Film* resume = nullptr;
    uint32_t resume_spp = 0;
    // Called between passes, at most every checkpoint_interval seconds, with the film and
    // the samples per pixel it holds (to write a checkpoint). Empty: never.
    std::function<void(const Film&, uint32_t spp)> checkpoint;
    double checkpoint_interval = 300;
};

struct RenderStats {
    double seconds = 0;
    uint64_t rays = 0;
    uint64_t camera_samples = 0;  // over all pixels (fewer than w h spp when adaptive)
    uint64_t nonfinite_samples = 0;
    // Samples per pixel in the film, resumed ones included (the most, if adaptive).
    uint32_t spp = 0;
    uint64_t active_pixels = 0;  // adaptive: pixels not converged when the render ended
    int passes = 0;
    bool interrupted = false;  // stopped by a user interrupt before options.spp
    bool aborted = false;      // second interrupt: the last pass is incomplete
};

// Adds sample indices [first, last) of every pixel to film (the camera's size), in
// index order per pixel: rendering [0,k) then [k,n) equals [0,n) bit for bit. With
// `active` (one flag per pixel, row-major), only the flagged pixels take samples. A film
// with the error AOV or denoising (AovSet::splits_halves) draws odd sample indices from a
// second, independent sample stream; one that denoises also traces each sample's guide
// (integrators/denoise_guide.h).
// Returns false when a second interrupt abandoned the pass; the film is then inconsistent.
bool render_samples(const RenderContext& ctx, const Camera& camera, const Integrator& integrator,
                    const RenderOptions& options, Film& film, uint32_t first, uint32_t last,
                    ProgressReporter* progress = nullptr,
                    const std::vector<uint8_t>* active = nullptr);

// How many samples per pixel the next pass should render when `done` took `elapsed`
// seconds: as many again as are done (so passes cost little), but no pass predicted to
// last over max_pass_seconds (an interrupt is then honoured soon) or to end after
// time_limit (when > 0). 0: stop.
uint32_t next_pass_samples(uint32_t done, uint32_t budget, double elapsed, double time_limit,
                           double max_pass_seconds = 2.0);

// Renders options.spp samples per pixel in passes (1, 1, 2, 4, ... samples, shortened
// to keep each pass to a few seconds and within the time limit) so that an interrupt
// or the time limit stops between passes. stats->spp says how many were rendered.
// With a target error the passes are fixed instead (adaptive_min_spp, then
// adaptive_step), so which pixels stop depends on the film alone; a time limit or an
// interrupt then ends the render after a whole pass.
Film render(const RenderContext& ctx, const Camera& camera, const Integrator& integrator,
            const RenderOptions& options, RenderStats* stats = nullptr);

}  // namespace penumbra
