#include "apps/penumbra/denoise_step.h"

#include <tbb/task_arena.h>

#include <chrono>

namespace penumbra {

std::string too_few_samples_to_denoise(uint32_t spp) {
    return "not denoised: " + std::to_string(spp) + " sample" + (spp == 1 ? "" : "s") +
           " per pixel, and the denoiser needs at least " + std::to_string(kDenoiseMinSpp) +
           " (it compares two halves of each pixel's samples)";
}

std::unique_ptr<DenoiseStep> denoise(const DenoiseInput& input, int threads,
                                     const NforParams& params) {
    auto step = std::make_unique<DenoiseStep>();
    step->params = params;
    const auto start = std::chrono::steady_clock::now();
    // In an arena of the render's size, so that --threads bounds the denoiser too.
    tbb::task_arena arena(threads > 0 ? threads : tbb::this_task_arena::max_concurrency());
    arena.execute([&] { step->result = denoise_nfor(input, params); });
    step->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    step->beauty = {&step->result.color, describe(params), step->result.relmse_estimate,
                    step->result.relmse_estimate_stderr, step->result.firefly_energy};
    return step;
}

std::unique_ptr<DenoiseStep> denoise_film(const Film& film, int threads, const NforParams& params) {
    return denoise(film.denoise_input(), threads, params);
}

}  // namespace penumbra
