// `penumbra converge`'s measurements: a configuration rendered at each checkpoint
// (doubling spp, time limits, or adaptive targets) and measured against the reference.
// A configuration with --denoise gives two series side by side: the raw renders and the
// same renders denoised, timed with the denoiser's cost.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "apps/penumbra/study/converge_command.h"
#include "core/image.h"

namespace penumbra {

struct ConvergeConfig {
    std::string name;
    RenderCommandOptions options;
};

struct ConvergePoint {
    uint32_t spp = 0;
    double seconds = 0, cpu_seconds = 0, mse = 0, relmse = 0;
    double variance = 0;         // --bias-variance (raw series): the halves' estimate, relative
    double mean_spp = 0;         // samples per pixel on average (below spp when adaptive)
    double target_error = 0;     // adaptive configurations: the target of this render
    double relmse_estimate = 0;  // denoised series: the denoiser's own estimate
    double time(const std::string& clock) const { return clock == "cpu" ? cpu_seconds : seconds; }
};

struct ConvergeSeries {
    std::string name;    // the configuration's, "NAME denoised" for the denoised one
    std::string config;  // the configuration's name
    bool denoised = false;
    std::vector<ConvergePoint> points;
};

// The configuration's raw series, then with --denoise its denoised one. Prints a line
// per checkpoint unless the configuration is quiet. Throws SceneError when the
// configuration's image size is not the reference's.
std::vector<ConvergeSeries> measure_config(const ConvergeOptions& o, const ConvergeConfig& c,
                                           const Image& ref);

}  // namespace penumbra
