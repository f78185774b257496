#include "apps/penumbra/batch.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "apps/penumbra/denoise_step.h"
#include "core/error.h"
#include "core/progress.h"
#include "io/image/image_writer.h"
#include "job/job_file.h"
#include "job/option_table.h"
#include "job/render_output.h"

namespace penumbra {

namespace fs = std::filesystem;

namespace {

std::string default_name(const RenderCommandOptions& o) {
    if (!o.views.empty())
        return o.frames.empty() ? "{scene}/{view}.exr" : "{scene}/{view}_{frame}.exr";
    return o.frames.empty() ? "{scene}.exr" : "{scene}_{frame}.exr";
}

// The entry's views, read once for all its jobs; null without --views. Several views
// need a name that tells them apart.
std::shared_ptr<const ViewList> entry_views(const RenderCommandOptions& o,
                                            const std::string& where) {
    if (o.views.empty()) return nullptr;
    auto views = std::make_shared<const ViewList>(read_views(o.views));
    const std::string& name = o.output.empty() ? o.name : o.output;
    if (views->size() > 1 && !uses_placeholder(name, "view") && !uses_placeholder(name, "camera") &&
        !uses_placeholder(name, "index"))
        throw SceneError((where.empty() ? std::string("--views") : where) + ": " +
                         std::to_string(views->size()) + " views would all write '" + name +
                         "'; add {view}, {camera} or {index} to the name");
    if (!o.camera.empty())
        throw SceneError((where.empty() ? std::string("--views") : where) +
                         ": the views replace the file's camera; drop --camera '" + o.camera +
                         "'");
    return views;
}

// One job per view (if any) of each frame of the options' frame list, or of the
// options' time.
void add_jobs(const std::string& scene, const RenderCommandOptions& o, const std::string& where,
              std::vector<BatchJob>& jobs) {
    BatchJob job;
    job.scene = scene;
    job.options = o;
    job.where = where;
    if (job.options.name.empty()) job.options.name = default_name(o);
    validate_options(job.options, where.empty() ? "options" : where);
    job.views = entry_views(job.options, where);
    std::vector<int> frames;
    try {
        if (!o.frames.empty()) frames = parse_frame_list(o.frames);
    } catch (const std::invalid_argument& e) {
        throw SceneError((where.empty() ? std::string("--frames") : where) + ": " + e.what());
    }
    const bool framed = !frames.empty();
    if (!framed) frames.push_back(0);
    job.source = jobs.empty() ? 0 : jobs.back().source + 1;
    for (int f : frames) {
        if (framed) job.options.timeline.frame = f;
        job.group = jobs.empty() ? 0 : jobs.back().group + 1;
        const size_t views = job.views ? job.views->size() : 0;
        for (size_t v = 0; v < std::max<size_t>(views, 1); ++v) {
            job.view = job.views ? int(v) : -1;
            jobs.push_back(job);
        }
    }
}

}  // namespace

void apply_settings(const JobSettings& settings, RenderCommandOptions& o, bool job_keys) {
    // A frame, frame range, time or shutter interval replaces the timing it inherits.
    const bool timing = std::any_of(settings.begin(), settings.end(),
                                    [](const JobSetting& s) { return s.option->timing; });
    if (timing) {
        o.frames.clear();
        o.timeline.frame.reset();
        o.timeline.time.reset();
        o.timeline.shutter_open.reset();
        o.timeline.shutter_close.reset();
    }
    for (const JobSetting& s : settings) {
        if (job_keys && s.option->job_set) s.option->job_set(o, s.text);
        else s.option->set(o, s.text);
    }
}

void validate_options(const RenderCommandOptions& o, const std::string& where) {
    try {
        expand_output_name(o.output.empty() ? o.name : o.output, {});
        TimelineSettings timeline = o.timeline;
        if (!o.frames.empty()) {
            if (timeline.frame) throw std::invalid_argument("--frame conflicts with --frames");
            timeline.frame = 0;  // each frame of the list is checked the same way
        }
        resolve_shutter(timeline);
        // Adaptive sampling gives every pixel at least two samples (its first pass is
        // even), so only the budget can leave a half empty.
        if (o.denoise && o.spp < kDenoiseMinSpp)
            throw std::invalid_argument(
                "denoise needs at least " + std::to_string(kDenoiseMinSpp) +
                " samples per pixel, spp is " + std::to_string(o.spp) +
                " (the denoiser compares two halves of each pixel's samples)");
        if (o.lens.fstop > 0 && o.lens.aperture_radius >= 0)
            throw std::invalid_argument("--fstop excludes --aperture-radius: give one");
        // Adaptive sampling stops a pixel by the error of its 3x3 neighbourhood, so a
        // band's edge rows would depend on rows another task renders.
        if (o.bands > 1 && o.target_error > 0)
            throw std::invalid_argument(
                "\"bands\" cannot be combined with \"target_error\" (adaptive sampling "
                "decides each pixel from its neighbours, across band edges)");
    } catch (const std::invalid_argument& e) {
        throw SceneError(where + ": " + e.what());
    }
}

std::vector<BatchJob> plan_batch(const RenderCommandOptions& o) {
    std::vector<BatchJob> jobs;
    if (!o.job_file.empty()) {
        const JobFile file = read_job_file(o.job_file);
        RenderCommandOptions defaults = o;
        apply_settings(file.defaults, defaults);
        for (const JobEntry& entry : file.jobs) {
            RenderCommandOptions merged = defaults;
            apply_settings(entry.settings, merged);
            add_jobs(entry.scene, merged, entry.where, jobs);
        }
    }
    for (const std::string& scene : o.scenes) add_jobs(scene, o, "", jobs);
    if (jobs.empty()) throw SceneError("nothing to render: give scene files or --job FILE");
    for (size_t i = 0; i < jobs.size(); ++i) jobs[i].index = i;
    if (!o.output.empty() && o.output.find('{') == std::string::npos && o.job_file.empty() &&
        jobs.size() > 1)
        throw SceneError("-o names one file, but the batch has " + std::to_string(jobs.size()) +
                         " images; use --out-dir (and --name), or placeholders in -o");
    return jobs;
}

bool output_needs_camera(const BatchJob& job) {
    const RenderCommandOptions& o = job.options;
    return job.view < 0 && uses_placeholder(o.output.empty() ? o.name : o.output, "camera");
}

std::string output_path(const BatchJob& job, const std::string& camera) {
    const RenderCommandOptions& o = job.options;
    OutputNameFields fields;
    fields.scene = fs::path(job.scene).stem().string();
    fields.camera = job.view >= 0 ? job.views->name(size_t(job.view)) : camera;
    fields.view = std::max(job.view, 0);
    // Without a frame, {frame} is the frame the shutter opens on.
    const TimelineSettings& t = o.timeline;
    fields.frame = t.frame ? *t.frame
                           : static_cast<int>(std::lround(resolve_shutter(t).open * t.fps));
    fields.index = job.index;
    if (!o.output.empty()) return expand_output_name(o.output, fields);
    return (fs::path(o.out_dir) / expand_output_name(o.name, fields)).string();
}

std::pair<int, int> band_rows(int height, int band, int bands) {
    const auto row = [&](int b) { return int(int64_t(height) * b / bands); };
    return {row(band), row(band + 1)};
}

std::string band_output_path(const std::string& output, int band, int bands) {
    const fs::path p(output);
    char suffix[48];
    const int digits = int(std::to_string(bands).size());
    std::snprintf(suffix, sizeof suffix, ".band-%0*d-of-%d.exr", digits, band + 1, bands);
    return (p.parent_path() / (p.stem().string() + suffix)).string();
}

namespace {

// s right-aligned in a column `width` wide, as printf's %10s.
std::string pad(const std::string& s, size_t width) {
    return s.size() >= width ? s : std::string(width - s.size(), ' ') + s;
}

}  // namespace

std::string format_summary(const std::vector<JobResult>& results) {
    std::string out;
    auto line = [&out](const char* format, auto... values) {
        const int n = std::snprintf(nullptr, 0, format, values...);
        std::string buf(size_t(std::max(n, 0)) + 1, '\0');
        std::snprintf(buf.data(), buf.size(), format, values...);
        buf.resize(size_t(std::max(n, 0)));
        out += buf;
    };
    size_t width = 5;
    for (const JobResult& r : results)
        width = std::max(width, fs::path(r.scene).filename().string().size());
    // Denoised images add their estimate and the noisy image's error; without any, the
    // table has no denoiser columns.
    const bool denoised = std::any_of(results.begin(), results.end(), [](const JobResult& r) {
        return r.denoise_relmse_estimate.has_value();
    });
    auto sci = [](const std::optional<double>& v, bool ran) {
        char buf[32] = "-";
        if (ran && v) std::snprintf(buf, sizeof buf, "%.4e", *v);
        return std::string(buf);
    };
    auto denoise_columns = [&](const std::string& estimate, const std::string& noisy) {
        return denoised ? "  " + pad(estimate, 10) + "  " + pad(noisy, 10) : std::string();
    };
    // Images that drew a nearly-black or mostly-clipped warning: a column of their own,
    // so that one bad image among thousands stands out; without any, no such column.
    size_t black = 0, clipped = 0;
    for (const JobResult& r : results) {
        black += r.image_warning == "nearly black";
        clipped += r.image_warning == "mostly clipped";
    }
    auto image_column = [&](const std::string& flag) {
        return black + clipped > 0 ? "  " + pad(flag, 7) : std::string();
    };
    auto flag_of = [](const JobResult& r) {
        return r.image_warning == "nearly black"     ? std::string("BLACK")
               : r.image_warning == "mostly clipped" ? std::string("CLIPPED")
                                                     : std::string("-");
    };
    line("%-*s  %5s  %-7s  %8s  %7s  %8s  %10s%s%s  %s\n", int(width), "scene", "frame", "status",
         "time", "spp", "rays/s", "relMSE", denoise_columns("estimate", "noisy").c_str(),
         image_column("image").c_str(), "output / error");
    size_t counts[4] = {0, 0, 0, 0};
    for (const JobResult& r : results) {
        static const char* const kStatus[] = {"ok", "partial", "failed", "skipped"};
        ++counts[int(r.status)];
        const bool ran = r.status == JobStatus::Ok || r.status == JobStatus::Partial;
        const std::string frame = r.frame >= 0 ? std::to_string(r.frame) : "-";
        const std::string rate =
            ran && r.seconds > 0 ? format_count(r.rays / r.seconds) : std::string("-");
        const std::string note =
            r.message.empty() ? r.output : (r.output.empty() ? "" : r.output + ": ") + r.message;
        line("%-*s  %5s  %-7s  %8s  %7s  %8s  %10s%s%s  %s\n", int(width),
             fs::path(r.scene).filename().string().c_str(), frame.c_str(), kStatus[int(r.status)],
             ran ? format_duration(r.seconds).c_str() : "-",
             ran ? std::to_string(r.spp).c_str() : "-", rate.c_str(), sci(r.relmse, ran).c_str(),
             denoise_columns(sci(r.denoise_relmse_estimate, ran), sci(r.noisy_relmse, ran)).c_str(),
             image_column(flag_of(r)).c_str(), note.c_str());
    }
    const std::string flagged =
        black + clipped > 0 ? "; " + std::to_string(black) + " nearly black, " +
                                  std::to_string(clipped) + " mostly clipped (see their warnings)"
                            : std::string();
    line("%zu images: %zu ok, %zu partial, %zu failed, %zu skipped%s\n", results.size(), counts[0],
         counts[1], counts[2], counts[3], flagged.c_str());
    return out;
}

void print_summary(const std::vector<JobResult>& results) {
    std::fputs(format_summary(results).c_str(), stdout);
    std::fflush(stdout);
}

}  // namespace penumbra
