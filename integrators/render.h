// The render loop, in one place: the image is cut into tiles that TBB renders in
// parallel; every pixel sample seeds its sampler from (seed, pixel, sample index), so
// the image is bitwise identical for any thread count.
#pragma once

#include <cstdint>
#include <string>

#include "core/camera/camera.h"
#include "core/film/film.h"
#include "core/film/filter.h"
#include "core/sampling/sampler.h"
#include "integrators/integrator.h"

namespace penumbra {

struct RenderOptions {
    uint32_t spp = 16;
    uint64_t seed = 0;
    int threads = 0;  // 0: all hardware threads
    int tile_size = 16;
    SamplerType sampler = SamplerType::Stratified;
    std::string filter = "gaussian";
    bool progress = true;
    std::string label = "render";
};

struct RenderStats {
    double seconds = 0;
    uint64_t rays = 0;
    uint64_t camera_samples = 0;
    uint64_t nonfinite_samples = 0;
};

Film render(const RenderContext& ctx, const Camera& camera, const Integrator& integrator,
            const RenderOptions& options, RenderStats* stats = nullptr);

}  // namespace penumbra
