// `penumbra check-accel`: traces the same rays through every accelerator (Embree, our
// BVH with each split, the grid), reports agreement with Embree, build time, memory and
// speed, and optionally renders with each one and compares the images.
#pragma once

#include <string>
#include <vector>

#include "job/render_options.h"

namespace CLI {
class App;  // CLI/CLI.hpp, which only the .cpp files that build commands include
}

namespace penumbra {

struct CheckAccelOptions {
    std::string scene;
    size_t rays = 100000;  // random, shadow and bounce rays, each
    unsigned long long seed = 1;
    double threshold = 1e-5;  // largest fraction of disagreeing rays that passes
    int width = 256;          // camera rays: one per pixel; also the --images size
    bool images = false;
    unsigned spp = 4;  // --images
    // Also Embree under these instruction sets ("sse4.2", "avx2", "avx512"), each an
    // accelerator of its own checked against the default Embree.
    std::vector<std::string> embree_isas;
    // Its timeline: --time, --shutter-open/-close, --frame/--fps/--shutter.
    RenderCommandOptions timing;
};

void add_check_accel_command(CLI::App& app, CheckAccelOptions& options);
// Returns the exit status: 0 when every accelerator agrees with Embree within the
// threshold and no disagreement is classified "other".
int run_check_accel_command(const CheckAccelOptions& options);

}  // namespace penumbra
