#include "apps/penumbra/render_command.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>
#include <tuple>

#include "apps/penumbra/batch.h"
#include "apps/penumbra/denoise_step.h"
#include "apps/penumbra/group_scene.h"
#include "apps/penumbra/interrupt.h"
#include "apps/penumbra/light_check.h"
#include "apps/penumbra/option_cli.h"
#include "job/option_table.h"
#include "apps/penumbra/render_checkpoint.h"
#include "apps/penumbra/render_metadata.h"
#include "apps/penumbra/scene_setup.h"
#include "apps/penumbra/view_transforms.h"
#include "core/error.h"
#include "core/log.h"
#include "core/progress.h"
#include "integrators/render.h"
#include "job/checkpoint.h"
#include "io/image/image_writer.h"
#include "job/render_output.h"
#include "io/image/render_writer.h"

namespace penumbra {

namespace fs = std::filesystem;

void add_render_command(CLI::App& app, RenderCommandOptions& o) {
    CLI::App* cmd = app.add_subcommand(
        "render", "Render glTF scenes to linear EXR images (plus a PNG preview)");
    cmd->add_option("scenes", o.scenes,
                    "Scene files (.gltf or .glb); a missing or broken one is reported and the "
                    "others still render");
    cmd->add_option("--job", o.job_file,
                    "JSON job file: {\"defaults\": {...}, \"jobs\": [{\"scene\": ..., ...}]}; "
                    "see README")
        ->check(CLI::ExistingFile);
    add_declared_options(cmd, o, is_render_option);
}

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

std::string format_scientific(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4e", v);
    return buf;
}

// What the images of a batch share: the overall bar, the Ctrl-C count and the outputs
// claimed so far (two images must not write one file).
struct BatchState {
    BatchProgress& progress;
    const std::atomic<int>& interrupts;
    std::set<std::string> claimed;  // outputs of earlier images in this batch
};

// Claims the output for this job; an existing finished output means the job is done.
bool claim_output(const BatchJob& job, const std::string& output, BatchState& state,
                  JobResult& result) {
    result.output = output;
    const std::string key = fs::absolute(output).lexically_normal().string();
    if (!state.claimed.insert(key).second)
        throw SceneError(output + ": another image of this batch already writes it; add "
                                  "{frame}, {view}, {camera} or {index} to --name");
    if (!job.options.overwrite && fs::exists(output) && is_finished_render(output)) {
        result.status = JobStatus::Skipped;
        result.message = "exists (--overwrite renders it again)";
        return false;
    }
    // A farm band is done when its band file is (the merge has not run yet).
    const std::string band =
        job.band >= 0 ? band_output_path(output, job.band, job.options.bands) : "";
    if (!band.empty() && !job.options.overwrite && fs::exists(band) && is_finished_render(band)) {
        result.status = JobStatus::Skipped;
        result.message = "band exists (--overwrite renders it again)";
        return false;
    }
    return true;
}

// What one finished image's report reads.
struct ImageReport {
    const std::string& scene;
    const std::string& output;
    const std::string& preview;  // empty: none
    const RenderCommandOptions& o;
    const SceneSetup& setup;
    const RenderStats& stats;
    double write_seconds;
    const RenderFilesResult& written;
    const DenoiseStep* denoised;  // null: not denoised
};

// The lines on stderr after an image: what was rendered, how fast, the denoiser's
// estimate and the errors against --reference.
void print_image_report(const ImageReport& r) {
    const RenderStats& stats = r.stats;
    const SceneSetup& setup = r.setup;
    const double pixels = double(setup.width) * setup.height;
    const std::string spp_note =
        r.o.target_error > 0
            ? " at most, mean " +
                  std::to_string(int(std::lround(double(stats.camera_samples) / pixels))) +
                  " (adaptive), " + std::to_string(stats.active_pixels) + " pixels unconverged"
        : stats.spp < r.o.spp ? " of " + std::to_string(r.o.spp)
                              : "";
    const std::string nonfinite =
        stats.nonfinite_samples
            ? ", " + std::to_string(stats.nonfinite_samples) + " NaN/Inf samples discarded"
            : "";
    std::fprintf(stderr,
                 "%s -> %s%s%s%s\n"
                 "  %dx%d, %u spp%s, integrator %s, camera '%s'\n"
                 "  load %s, build %s (%zu meshes, %zu instances%s), render %s, write %s\n"
                 "  %.2f M rays/s (%llu rays), %.2f M samples/s, peak memory %s%s\n",
                 r.scene.c_str(), r.output.c_str(), r.preview.empty() ? "" : " + ",
                 r.preview.c_str(), stats.interrupted ? " (partial)" : "", setup.width,
                 setup.height, stats.spp, spp_note.c_str(), render_option("integrator").get(r.o).c_str(),
                 setup.camera_desc.name.c_str(), format_duration(setup.load_seconds).c_str(),
                 format_duration(setup.build_seconds).c_str(), setup.scene.objects.size(),
                 setup.scene.instances.size(),
                 setup.images > 1 ? "; loaded for an earlier view" : "",
                 format_duration(stats.seconds).c_str(),
                 format_duration(r.write_seconds).c_str(),
                 stats.seconds > 0 ? stats.rays / stats.seconds / 1e6 : 0.0,
                 static_cast<unsigned long long>(stats.rays),
                 stats.seconds > 0 ? stats.camera_samples / stats.seconds / 1e6 : 0.0,
                 format_bytes(peak_memory_bytes()).c_str(), nonfinite.c_str());
    if (r.denoised)
        std::fprintf(stderr, "  denoised in %s by %s: estimated relMSE %.4e\n",
                     format_duration(r.denoised->seconds).c_str(),
                     r.denoised->beauty.method.c_str(), r.denoised->result.relmse_estimate);
    if (r.written.mse)
        std::fprintf(stderr, "  MSE %.4e, relMSE %.4e against %s%s\n", *r.written.mse,
                     *r.written.relmse, r.o.reference.c_str(),
                     r.written.noisy_mse
                         ? (" (noisy: MSE " + format_scientific(*r.written.noisy_mse) +
                            ", relMSE " + format_scientific(*r.written.noisy_relmse) + ")")
                               .c_str()
                         : "");
}

// The render loop's options for the job: its frame and band in the progress label, the
// band's rows, the batch's interrupts and overall bar.
RenderOptions job_render_options(const BatchJob& job, int height, BatchState& state) {
    const RenderCommandOptions& o = job.options;
    RenderOptions ropt = render_options_for(o, fs::path(job.scene).filename().string());
    if (o.timeline.frame) ropt.label += " frame " + std::to_string(*o.timeline.frame);
    if (job.view >= 0) ropt.label += " " + job.views->name(size_t(job.view));
    if (job.band >= 0) {
        std::tie(ropt.row_begin, ropt.row_end) = band_rows(height, job.band, o.bands);
        ropt.label += " band " + std::to_string(job.band + 1) + "/" + std::to_string(o.bands);
    }
    ropt.interrupts = &state.interrupts;
    ropt.batch = &state.progress;
    return ropt;
}

// What the image writes to `output`, as the options say. band_input: a band's of a
// render that denoises.
RenderFiles render_files_for(const RenderCommandOptions& o, const std::string& output,
                             const DenoiseStep* denoised, const DenoiseInput* band_input) {
    RenderFiles files;
    files.exr = output;
    if (!o.no_preview) files.preview = preview_path_for(output);
    files.exposure = o.exposure;
    files.exr_options = {o.half, o.compression};
    files.reference = o.reference;
    if (denoised) files.denoised = &denoised->beauty;
    files.denoise_input = band_input;
    return files;
}

// Denoised after the render, before anything is written. A farm band is not: the
// denoiser's windows reach across band edges, so the band writes the denoiser's input
// and the merge denoises the assembled image (apps/penumbra/farm/farm_merge.cpp).
std::unique_ptr<DenoiseStep> denoise_job(const BatchJob& job, const Film& film, uint32_t spp,
                                         const std::string& output) {
    if (!job.options.denoise || job.band >= 0) return nullptr;
    // A time limit or an interrupt can stop a render after its first pass of one sample.
    if (spp < kDenoiseMinSpp) {
        LOG_WARNING(output << ": " << too_few_samples_to_denoise(spp));
        return nullptr;
    }
    return denoise_film(film, job.options.threads);
}

// The per-image pipeline: set up, render in passes, write. Errors propagate.
// A render's checkpoint: where it lives, what it must match, and what an earlier run of
// the same render left there.
struct JobCheckpoint {
    std::string path;
    std::string fingerprint;
    CheckpointState prior;
};

// Continue from a checkpoint of this very render into `resumed`; a stale or damaged one
// is named and the render starts from sample 0.
JobCheckpoint resume_from_checkpoint(const BatchJob& job, const SceneSetup& setup,
                                     const std::string& output, Film& resumed,
                                     RenderOptions& ropt) {
    const RenderCommandOptions& o = job.options;
    JobCheckpoint c{checkpoint_path(output), render_fingerprint(job, setup, ropt), {}};
    std::string why;
    if (const auto state_read = read_checkpoint(c.path, c.fingerprint, resumed, &why)) {
        c.prior = *state_read;
        ropt.resume = &resumed;
        ropt.resume_spp = c.prior.spp;
        if (!o.quiet)
            std::fprintf(stderr, "%s: resuming from the checkpoint at %u of %u spp\n",
                         output.c_str(), c.prior.spp, o.spp);
    } else if (fs::exists(c.path)) {
        LOG_WARNING(why << "; rendering from sample 0");
    }
    return c;
}

// Writes the rendered film (denoised, with its header and any warning about how it
// looks), drops the checkpoint of a finished render and reports the image.
void write_job_outputs(const BatchJob& job, const SceneSetup& setup, const Film& film,
                       const RenderStats& stats, const std::string& output,
                       const std::string& ckpt, JobResult& result) {
    const RenderCommandOptions& o = job.options;
    const std::string& path = job.scene;
    Metadata metadata = render_metadata(o, path, setup, stats);
    // A band is a part of the image: the merged image is what a viewer sees.
    const std::optional<ImageWarning> warning =
        job.band < 0 ? image_warning(measure_exposure(film.resolve(), o.exposure), o,
                                    light_facts(setup))
                     : std::nullopt;
    if (warning) {
        metadata.push_back({"penumbra:image_warning", warning->message});
        result.image_warning = warning->kind;
    }
    const std::unique_ptr<DenoiseStep> denoised = denoise_job(job, film, stats.spp, output);
    if (denoised && o.timing_metadata)
        metadata.push_back({"penumbra:denoise_seconds", float(denoised->seconds)});
    const DenoiseInput band_input =
        o.denoise && job.band >= 0 ? film.denoise_input() : DenoiseInput();
    const auto t0 = Clock::now();
    const RenderFiles files =
        render_files_for(o, output, denoised.get(), band_input.width() > 0 ? &band_input : nullptr);
    const RenderFilesResult written =
        write_render(files, film, *setup.color, setup.camera_desc, std::move(metadata));
    result.relmse = written.relmse;
    result.noisy_relmse = written.noisy_relmse;
    if (denoised) result.denoise_relmse_estimate = denoised->result.relmse_estimate;
    result.peak_memory = peak_memory_bytes();
    std::error_code ec;
    if (!stats.interrupted) fs::remove(ckpt, ec);
    const double write_s = since(t0);
    result.status = stats.interrupted ? JobStatus::Partial : JobStatus::Ok;
    if (stats.interrupted)
        result.message = "interrupted: partial image; the same command continues it from " + ckpt;
    if (!o.quiet)
        print_image_report(
            {path, output, files.preview, o, setup, stats, write_s, written, denoised.get()});
    // Last, where a batch's log is read: the image exists, and why it looks wrong.
    if (warning) LOG_WARNING(output << ": " << warning->message);
}

void render_job(const BatchJob& job, GroupScene& scene, BatchState& state, JobResult& result) {
    const RenderCommandOptions& o = job.options;
    // Without {camera} the output name is known before loading: skip without loading.
    if (!output_needs_camera(job) && !claim_output(job, output_path(job, ""), state, result))
        return;
    SceneSetup* const setup = &group_setup(job, scene);
    const CameraDesc& cam_desc = setup->camera_desc;
    if (output_needs_camera(job) &&
        !claim_output(job, output_path(job, cam_desc.name), state, result))
        return;
    // A band renders its rows into its own file; the merge writes result.output.
    const std::string output = job.band >= 0
                                   ? band_output_path(result.output, job.band, o.bands)
                                   : result.output;

    RenderOptions ropt = job_render_options(job, setup->height, state);

    Film resumed(setup->width, setup->height, ropt.aovs);
    const JobCheckpoint checkpoint = resume_from_checkpoint(job, *setup, output, resumed, ropt);
    const std::string& ckpt = checkpoint.path;
    const std::string& fingerprint = checkpoint.fingerprint;
    const CheckpointState& prior = checkpoint.prior;
    const uint64_t rays_start = setup->accel->rays_traced();
    const auto render_start = Clock::now();
    auto save_checkpoint = [&](const Film& f, uint32_t spp) {
        write_checkpoint(ckpt, f,
                         {fingerprint, spp, prior.rays + setup->accel->rays_traced() - rays_start,
                          prior.seconds + since(render_start)});
    };
    ropt.checkpoint_interval = o.checkpoint_interval;
    // A timed checkpoint that cannot be written (disk full) costs only the insurance;
    // the render goes on. The one on an interrupt below does fail the image.
    if (o.checkpoint_interval > 0)
        ropt.checkpoint = [&](const Film& f, uint32_t spp) {
            try {
                save_checkpoint(f, spp);
            } catch (const std::exception& e) {
                LOG_WARNING(e.what() << "; rendering on without a checkpoint");
            }
        };

    RenderStats stats;
    const Film film = render(setup->context(), *setup->camera, *setup->integrator, ropt, &stats);
    stats.rays += prior.rays;
    stats.seconds += prior.seconds;
    result.seconds = stats.seconds;
    result.spp = stats.spp;
    result.rays = stats.rays;
    if (stats.aborted || stats.spp == 0) {
        // A second Ctrl-C, or one before the first pass: there is no image to keep (an
        // earlier checkpoint stays for the next run).
        result.status = JobStatus::Failed;
        result.message = "interrupted before an image was complete; nothing written";
        return;
    }
    // Stopped early by a signal: the checkpoint first, so the partial image never
    // exists without what continues it.
    if (stats.interrupted) save_checkpoint(film, stats.spp);

    write_job_outputs(job, *setup, film, stats, output, ckpt, result);
}

}  // namespace

int run_render_command(const RenderCommandOptions& o) {
    if (o.quiet) set_log_level(LogLevel::Error);
    const std::vector<BatchJob> jobs = plan_batch(o);
    std::vector<JobResult> results;
    const int status = run_render_jobs(jobs, o, results);
    if (!o.quiet && results.size() > 1) print_summary(results);
    return status;
}

int run_render_jobs(const std::vector<BatchJob>& jobs, const RenderCommandOptions& o,
                    std::vector<JobResult>& results) {
    const InterruptScope interrupt;
    BatchProgress progress(jobs.size(), !o.quiet && jobs.size() > 1);
    BatchState state{progress, interrupt.count(), {}};
    GroupScene scene;
    const size_t first_result = results.size();
    for (size_t i = 0; i < jobs.size(); ++i) {
        const BatchJob& job = jobs[i];
        JobResult r;
        r.scene = job.scene;
        r.frame = job.options.timeline.frame.value_or(-1);
        if (interrupt.signals() > 0) {
            r.status = JobStatus::Skipped;
            r.message = "interrupted before it started";
        } else {
            try {
                scene.more_frames = more_frames(jobs, i);
                render_job(job, scene, state, r);
            } catch (const std::exception& e) {
                // One bad scene does not stop the batch.
                std::fprintf(stderr, "error: %s\n", e.what());
                r.status = JobStatus::Failed;
                r.message = e.what();
            }
            if (r.status == JobStatus::Skipped && !o.quiet)
                std::fprintf(stderr, "%s: skipped, %s %s\n", job.scene.c_str(), r.output.c_str(),
                             r.message.c_str());
        }
        progress.job_finished(r.rays);
        results.push_back(r);
        const bool last = i + 1 == jobs.size();
        if (last || jobs[i + 1].group != job.group) {
            if (scene.setup && scene.group == job.group)
                write_view_transforms(jobs, results, first_result, job.group, *scene.setup);
            end_group(scene, last || jobs[i + 1].source != job.source);
        }
    }
    const auto failed = std::count_if(results.begin(), results.end(), [](const JobResult& r) {
        return r.status == JobStatus::Failed;
    });
    // 128 + the signal, as a shell reports a command stopped by Ctrl-C or SIGTERM.
    if (interrupt.signals() > 0) return interrupt.exit_status();
    return failed ? 1 : 0;
}

}  // namespace penumbra
