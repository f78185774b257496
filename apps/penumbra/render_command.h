// `penumbra render`: options, the per-image pipeline (set up, render in passes, write)
// and the batch around it (scenes x frames or a job file, resume, summary table).
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "io/color/color.h"
#include "io/image/image_reader.h"
#include "job/timeline.h"

namespace penumbra {

struct RenderCommandOptions {
    std::vector<std::string> scenes;
    std::string output;   // -o: a file, or a name template when the batch has several images
    std::string out_dir = "out";
    std::string name;     // --name template in out_dir; empty: {scene}.exr ({scene}_{frame})
    std::string job_file;              // --job: JSON batch description
    std::string frames;                // --frames "1-48", "3", "1,5,10-12"
    // --time, --shutter-open/--shutter-close, --frame/--fps/--shutter; a batch sets
    // `frame` for each of --frames.
    TimelineSettings timeline;
    double time_limit = 0;  // seconds per image; 0: none
    bool overwrite = false; // re-render images whose complete output exists
    bool no_preview = false;
    int width = 0, height = 0;  // 0: derived from the camera's aspect ratio
    unsigned spp = 16;
    int threads = 0;
    unsigned long long seed = 0;
    std::string camera;   // name or index; empty: the first camera, or a default one
    std::string variant;  // KHR_materials_variants name; empty: default materials
    std::string integrator = "path";
    std::string strategy = "mis";
    std::string light_sampler = "auto";      // uniform | power | bvh | auto
    std::string triangle_sampling = "area";  // area | solid-angle
    std::string env_sampling = "auto";       // auto | full | compensated
    std::string microfacet = "ggx";  // glTF specular lobes: ggx | beckmann
    std::string gltf_layering = "albedo-scaled";  // glTF diffuse base: albedo-scaled | spec
    int light_samples = 1, bsdf_samples = 1;
    std::string env;            // equirectangular image
    std::vector<float> env_color;  // constant environment radiance (r g b)
    float env_intensity = 1, env_rotation = 0;
    std::string sampler = "tabled-sobol";
    std::string filter = "gaussian";
    std::string accel = "embree";
    int max_depth = 8;
    // Depth of field overrides (0 / empty: keep the file's values; aperture_radius -1
    // keeps the file's, 0 is a pinhole).
    float fstop = 0, aperture_radius = -1, focus_distance = 0;
    int aperture_blades = -1;
    std::vector<float> focus_on;  // raster x y
    // Default key and fill lights: auto (when the scene's own light is too weak; see
    // scene_setup.cpp), on, off.
    std::string default_light = "auto";
    std::string light_units = "photometric";  // KHR_lights_punctual: photometric | radiometric
    bool no_file_lights = false;              // leave out the file's punctual lights
    bool strict = false;  // every scene warning is an error (GltfLoadOptions::strict)
    uint64_t max_texture_pixels = kDefaultMaxTexturePixels;  // larger images are refused
    bool quiet = false;
    // Colour management and EXR output (output_options.cpp).
    ColorSettings color;
    std::string aovs;                 // --aov list; empty: none
    bool half = false;
    float exposure = 0;               // stops: the EXR and the preview are scaled by 2^exposure
    std::string compression = "zip";
    std::string reference;            // EXR to measure MSE and relMSE against
    bool timing_metadata = false;     // render time in the header (not reproducible)
    // Adaptive sampling and firefly control (sampling_options.cpp); 0: off.
    double target_error = 0;
    unsigned adaptive_min_spp = 0;
    float clamp_direct = 0, clamp_indirect = 0, regularize = 0;
    // --denoise: the EXR's RGB is denoised after rendering; the samples then form two
    // independently seeded halves, as the error AOV's (sampling_options.cpp).
    bool denoise = false;
    // Checkpoints (job/checkpoint.h): written on an interrupt and every this many seconds
    // between passes; 0: only on an interrupt.
    double checkpoint_interval = 300;
    int bands = 1;  // the job key "bands": row bands per image on the farm
    int frames_per_task = 1;  // the job key "frames_per_task": frames per farm task
};

void add_render_command(CLI::App& app, RenderCommandOptions& options);
// Renders every image of the batch; one failing scene does not stop the others. Returns
// the exit status: 0 when all rendered or were skipped, 1 if any failed, 130 after
// Ctrl-C.
int run_render_command(const RenderCommandOptions& options);

struct BatchJob;
struct JobResult;
// Renders the given jobs of a batch (as run_render_command does after planning it) and
// returns the exit status: 0, 1 if any failed, 128 + the signal after an interrupt.
int run_render_jobs(const std::vector<BatchJob>& jobs, const RenderCommandOptions& options,
                    std::vector<JobResult>& results);

}  // namespace penumbra
