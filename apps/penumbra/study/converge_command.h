// `penumbra converge`: speed against error. Renders a scene at doubling sample counts
// (or time checkpoints) in one or more configurations, measures each image against a
// reference, and writes convergence.csv, a log-log convergence.svg and summary.txt. A
// configuration with --target-error sweeps the target instead of the spp, so the time to
// an error compares adaptive sampling with uniform sampling. A configuration with
// --denoise also denoises each render: a second series, "NAME denoised", beside the raw
// one, its time including the denoiser's, with the denoiser's own relMSE estimate.
#pragma once

#include <string>
#include <vector>

#include "apps/penumbra/render_command.h"

namespace CLI {
class App;  // CLI/CLI.hpp, which only the .cpp files that build commands include
}

namespace penumbra {

struct ConvergeOptions {
    std::string scene;
    std::string reference;        // an EXR to compare against
    unsigned reference_spp = 0;   // or: render the reference first, with this many spp
    std::string out_dir;          // -o
    unsigned max_spp = 64, min_spp = 1;
    std::vector<double> times;    // time checkpoints in seconds, instead of doubling spp
    std::string compare;          // "name=OPTIONS;name=OPTIONS"
    std::vector<std::string> configs;  // "NAME:OPTIONS", repeatable
    double target_relmse = 1e-2;
    double epsilon = 1e-2;        // relMSE = mean((x - r)^2 / (r^2 + epsilon))
    std::string clock = "wall";   // time for plot and efficiency: wall | cpu
    // Split each relMSE into the variance the image's two halves estimate and the rest
    // (bias^2, plus the reference's own noise): every render then takes the error AOV.
    bool bias_variance = false;
    RenderCommandOptions base;    // the image options every configuration starts from
};

void add_converge_command(CLI::App& app, ConvergeOptions& options);
// Returns the exit status.
int run_converge_command(const ConvergeOptions& options);

}  // namespace penumbra
