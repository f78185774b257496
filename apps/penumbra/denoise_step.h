// Denoising a finished render in the process that rendered it: the denoiser run on the
// film's buffers with the render's thread count, its result in the form write_render
// takes (io/render_writer.h). Shared by `render` and `converge`.
#pragma once

#include <memory>

#include "core/denoise/nfor_denoiser.h"
#include "core/film/film.h"
#include "io/render_writer.h"

namespace penumbra {

struct DenoiseStep {
    NforParams params;
    DenoiseResult result;
    DenoisedBeauty beauty;  // points into result
    double seconds = 0;     // the denoiser's wall time
    DenoiseStep() = default;
    DenoiseStep(const DenoiseStep&) = delete;
    DenoiseStep& operator=(const DenoiseStep&) = delete;
};

// film must have been rendered with Aov::Denoise. threads: as RenderOptions::threads (0:
// all); the image is the same for any count.
std::unique_ptr<DenoiseStep> denoise_film(const Film& film, int threads,
                                          const NforParams& params = {});

}  // namespace penumbra
