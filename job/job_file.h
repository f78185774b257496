// Batch job files: JSON with global defaults and one entry per scene that overrides
// them, validated like scene files (errors name the file and the element). Also the
// frame-list syntax shared by --frames and the job file's "frames".
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace penumbra {

// Settings a job file may give, globally ("defaults") or per entry. Unset: inherit.
// Relative paths (scene, output, out_dir) are resolved against the job file's folder.
struct JobSettings {
    std::optional<std::string> camera, variant, integrator, strategy, sampler, filter, accel;
    // as --light-sampler, --triangle-sampling, --env-sampling
    std::optional<std::string> light_sampler, triangle_sampling, env_sampling;
    std::optional<std::string> output, out_dir, name, frames;
    std::optional<int> width, height, max_depth, frame;
    // `penumbra farm`: split each image into this many row bands, one farm task each
    // (`render --job` ignores it: one machine renders whole images).
    std::optional<int> bands;
    // `penumbra farm`: consecutive frames of an entry rendered by one task (fewer, longer
    // tasks for a scheduler that starts only so many per second; docs/farm.md).
    std::optional<int> frames_per_task;
    std::optional<uint32_t> spp;
    std::optional<uint64_t> seed;
    // Timeline: time (an instant), shutter_open + shutter_close (seconds), or frame /
    // frames with fps and shutter (a fraction of a frame); see job/timeline.h.
    std::optional<double> time, time_limit, fps, shutter, shutter_open, shutter_close;
    // Colour and EXR output, as the command line's --ocio-config, --working-space,
    // --output-colorspace, --display, --view, --look, --aov, --half, --compression.
    std::optional<std::string> ocio_config, working_space, output_colorspace, display, view,
        look, aov, compression;
    std::optional<bool> half;
    // Light: as --light-units, --default-light and --exposure (stops).
    std::optional<std::string> light_units, default_light;
    std::optional<double> exposure;
    std::optional<bool> no_file_lights;  // as --no-file-lights
    // As --strict and --max-texture-pixels.
    std::optional<bool> strict;
    std::optional<uint64_t> max_texture_pixels;
    // Adaptive sampling and firefly control, as --target-error, --adaptive-min-spp,
    // --clamp-direct, --clamp-indirect and --regularize.
    std::optional<double> target_error, clamp_direct, clamp_indirect, regularize;
    std::optional<int> adaptive_min_spp;
    // As --denoise.
    std::optional<bool> denoise;
};

struct JobEntry {
    std::string scene;
    JobSettings settings;
    std::string where;  // "jobs.json: jobs[2]", for messages
};

struct JobFile {
    JobSettings defaults;
    std::vector<JobEntry> jobs;
};

// Throws SceneError naming the file and element for bad JSON, unknown keys, wrong types
// or out-of-range values.
JobFile read_job_file(const std::string& path);
// As read_job_file, from text; `path` names it in messages and anchors relative paths.
JobFile parse_job_file(const std::string& text, const std::string& path);

// "12", "1-48", "1-48:4" (every 4th), or a comma-separated list of those, in order.
// Throws std::invalid_argument with the reason.
std::vector<int> parse_frame_list(const std::string& spec);

}  // namespace penumbra
