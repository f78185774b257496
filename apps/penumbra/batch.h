// A batch of images: the scenes (times frames) from the command line and a job file,
// each with its merged options and output path, and the summary table at the end.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "apps/penumbra/render_command.h"
#include "job/job_file.h"
#include "job/view_list.h"

namespace penumbra {

struct BatchJob {
    std::string scene;
    RenderCommandOptions options;  // command line < job file defaults < job entry
    std::string where;             // "jobs.json: jobs[2]" for job file entries
    size_t index = 0;              // position in the batch, from 0 ({index})
    // A farm task renders one row band of options.bands into band_output_path(); -1: the
    // whole image (`render --job` always renders whole images).
    int band = -1;
    // --views: this image's view (-1: none) among every view of its entry.
    int view = -1;
    std::shared_ptr<const ViewList> views;
    // Consecutive jobs of one source (every frame and view of one scene argument or job
    // entry: the same file with the same options but for their timing) render from one
    // loaded file, posed per frame; those of one group (the views of one frame) from one
    // pose and one accelerator; only the camera changes between them.
    size_t source = 0;
    size_t group = 0;
};

// Sets the settings over o in order, as a job entry's keys go over its defaults: a timing
// key (frame, time, shutter) replaces all the timing o had. job_keys: a key with a job-file
// meaning of its own takes it ("frame" is a frame list of one); else every key is `set`.
void apply_settings(const JobSettings& settings, RenderCommandOptions& o, bool job_keys = true);
// Checks what spans options, or what the command line checks with CLI11 but a job file or
// a Python call can spell freely (a denoised render's samples, --fstop against
// --aperture-radius, ...). Throws SceneError starting with `where`.
void validate_options(const RenderCommandOptions& o, const std::string& where);

// Expands scenes x frames x views and the job file's entries, in order. Throws SceneError for a
// bad job file, frame list or option value, before anything renders.
std::vector<BatchJob> plan_batch(const RenderCommandOptions& o);

// The job's output: -o or the job's "output" (both may hold placeholders), else
// out_dir/name. The camera name is only known once the scene is loaded, except a view's.
std::string output_path(const BatchJob& job, const std::string& camera);
bool output_needs_camera(const BatchJob& job);

// Rows [first, last) of band `band` of `bands` in an image `height` rows tall, as even
// as whole rows allow; bands beyond the height are empty.
std::pair<int, int> band_rows(int height, int band, int bands);
// Where a band is written until the merge assembles the output: beside it, as
// NAME.band-B-of-N.exr (B and N from 1 and 0-padded, so they sort).
std::string band_output_path(const std::string& output, int band, int bands);

enum class JobStatus { Ok, Partial, Failed, Skipped };

struct JobResult {
    std::string scene, output, message;  // message: the error, or why it was skipped
    int frame = -1;
    JobStatus status = JobStatus::Failed;
    double seconds = 0;  // rendering only
    uint32_t spp = 0;
    uint64_t rays = 0;
    uint64_t peak_memory = 0;      // of the process when the image was done
    std::optional<double> relmse;  // against --reference, when given
    // --denoise: the denoiser's estimate of the image's relMSE, and the relMSE of the
    // noisy image (before denoising) against --reference, when given.
    std::optional<double> denoise_relmse_estimate, noisy_relmse;
    // "nearly black" or "mostly clipped" when the image drew that warning; else empty.
    std::string image_warning;
};

// One row per job: scene, frame, status, time, spp, rays/s, relMSE against the
// reference (when given), and the output or error. When some image was denoised, two
// more columns: the denoiser's estimated relMSE and the noisy image's relMSE.
void print_summary(const std::vector<JobResult>& results);
std::string format_summary(const std::vector<JobResult>& results);

}  // namespace penumbra
