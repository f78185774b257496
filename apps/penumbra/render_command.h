// `penumbra render`: options and the per-scene pipeline (load, build, render, write).
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace penumbra {

struct RenderCommandOptions {
    std::vector<std::string> scenes;
    std::string output;   // -o: only with a single scene
    std::string out_dir = "out";
    bool no_preview = false;
    int width = 0, height = 0;  // 0: derived from the camera's aspect ratio
    unsigned spp = 16;
    int threads = 0;
    unsigned long long seed = 0;
    std::string camera;   // name or index; empty: the first camera, or a default one
    std::string integrator = "path";
    std::string strategy = "mis";
    int light_samples = 1, bsdf_samples = 1;
    std::string env;            // equirectangular image
    std::vector<float> env_color;  // constant environment radiance (r g b)
    float env_intensity = 1, env_rotation = 0;
    std::string sampler = "stratified";
    std::string filter = "gaussian";
    std::string accel = "embree";
    int max_depth = 8;
    bool default_light = true;
    bool quiet = false;
};

void add_render_command(CLI::App& app, RenderCommandOptions& options);
// Renders every scene; one failing scene does not stop the others. Returns the exit
// status: 0 when all succeeded.
int run_render_command(const RenderCommandOptions& options);

}  // namespace penumbra
