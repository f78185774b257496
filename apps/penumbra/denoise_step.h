// Denoising a finished render: the denoiser run on the film's buffers (or, in the farm's
// merge, on the input assembled from row bands) with the render's thread count, its
// result in the form write_render takes (io/image/render_writer.h). Shared by `render`,
// `converge` and `farm merge`.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "core/denoise/nfor_denoiser.h"
#include "core/film/film.h"
#include "io/image/render_writer.h"

namespace penumbra {

// The fewest samples per pixel a render is denoised with: the denoiser compares the two
// halves of each pixel's samples, and below two one half is empty, which leaves it no
// variance and no cross-validation (its estimate comes out meaningless, even negative).
inline constexpr uint32_t kDenoiseMinSpp = 2;
// Why a render of spp samples per pixel (below kDenoiseMinSpp) is not denoised.
std::string too_few_samples_to_denoise(uint32_t spp);

struct DenoiseStep {
    NforParams params;
    DenoiseResult result;
    DenoisedBeauty beauty;  // points into result
    double seconds = 0;     // the denoiser's wall time
    DenoiseStep() = default;
    DenoiseStep(const DenoiseStep&) = delete;
    DenoiseStep& operator=(const DenoiseStep&) = delete;
};

// input: as Film::denoise_input gives it. threads: as RenderOptions::threads (0: all);
// the image is the same for any count.
std::unique_ptr<DenoiseStep> denoise(const DenoiseInput& input, int threads,
                                     const NforParams& params = {});
// film must have been rendered with Aov::Denoise.
std::unique_ptr<DenoiseStep> denoise_film(const Film& film, int threads,
                                          const NforParams& params = {});

}  // namespace penumbra
