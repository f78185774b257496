#include "apps/penumbra/farm/farm_merge.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "apps/penumbra/denoise_step.h"
#include "apps/penumbra/farm/farm_plan.h"
#include "apps/penumbra/light_check.h"
#include "core/error.h"
#include "core/log.h"
#include "io/atomic_file.h"
#include "job/band_merge.h"
#include "io/color/color.h"
#include "io/image/denoise_layers.h"
#include "io/image/image_writer.h"
#include "job/render_output.h"
#include "io/image/render_writer.h"

namespace penumbra {

namespace fs = std::filesystem;

namespace {

std::string band_name(int band, int bands) {
    return "band " + std::to_string(band + 1) + "/" + std::to_string(bands);
}

// What the merge of a render that denoises adds to the assembled image's file.
struct MergedDenoise {
    HeaderStrings attributes;  // penumbra:denoise and its estimate
    Image preview;             // the preview's image (Beauty::working); empty: none
};

// The merge of a render that denoises, after the bands are assembled: the whole image's
// denoiser input from the bands' layers, denoised as one machine denoises (the same
// parameters, and the same bits for any thread count), and the file made as write_render
// makes a denoised render's: the RGB denoised in the job's exposure and output space, the
// assembled RGB (the film's estimate) as the layer Noisy. The input's layers are left out.
MergedDenoise denoise_merged(const BatchJob& job, const ColorPipeline& color, MergedImage& image,
                             uint32_t spp, JobResult& r) {
    const RenderCommandOptions& o = job.options;
    const DenoiseInput input = read_denoise_input(
        [&](const std::vector<std::string>& names) { return image.channels(names); });
    image.remove_channels(std::string(kDenoiseInputLayer) + ".");
    // A band stopped by its time limit after one sample leaves nothing to denoise with.
    if (spp < kDenoiseMinSpp) {
        LOG_WARNING(r.output << ": " << too_few_samples_to_denoise(spp));
        return {};
    }
    const std::unique_ptr<DenoiseStep> step = denoise(input, o.threads);
    Beauty beauty =
        denoised_beauty(step->beauty, image.channels({"R", "G", "B", "A"}), o.exposure, color);
    image.insert_channels("A", {"Noisy.R", "Noisy.G", "Noisy.B"}, "R",
                          image.channels({"R", "G", "B"}));
    image.set_channels({"R", "G", "B", "A"}, beauty.output);
    r.denoise_relmse_estimate = step->result.relmse_estimate;
    MergedDenoise out{denoise_attributes(step->beauty), Image()};
    if (!o.no_preview) out.preview = std::move(beauty.working);
    return out;
}

// The warning one machine ends a nearly black or mostly clipped render with, for the
// assembled image: measured on its RGB as the bands wrote it (the film's estimate,
// already exposed, in the output space: the same pixels as one machine measures where
// the output space is the working space), with the scene's facts from the first band's
// header. Bands are parts of the image and do not warn themselves.
std::optional<ImageWarning> merged_image_warning(const BatchJob& job, const MergedImage& image,
                                                 const std::string& first_band) {
    LightFacts facts;
    facts.default_lights = image_attribute(first_band, "penumbra:default_lights_added", "0") == "1";
    facts.file_lights = std::stoull(image_attribute(first_band, "penumbra:file_lights", "0"));
    facts.generator = image_attribute(first_band, "penumbra:asset_generator", "");
    return image_warning(measure_exposure(image.channels({"R", "G", "B"})), job.options, facts);
}

// Merges the bands of one image whose tasks all rendered (or skipped) their band.
void merge_image(const BatchJob& job, const std::vector<TaskRecord>& bands, JobResult& r) {
    const int n = job.options.bands;
    r.output = bands[0].results.at(0).output;
    bool all_skipped = true;
    for (const TaskRecord& b : bands) all_skipped &= b.results[0].status == JobStatus::Skipped;
    if (all_skipped && fs::exists(r.output) && is_finished_render(r.output)) {
        r.status = JobStatus::Skipped;
        r.message = "exists (--overwrite renders it again)";
        return;
    }
    std::vector<BandFile> exr, png;
    uint64_t rays = 0, nonfinite = 0;
    uint32_t spp = ~0u;
    bool partial = false;
    int height = -1;
    for (int b = 0; b < n; ++b) {
        const std::string file = band_output_path(r.output, b, n);
        if (!fs::exists(file))
            throw SceneError(r.output + ": " + band_name(b, n) + " is missing (" + file + ")");
        if (height < 0) height = image_height(file);
        const auto [row0, row1] = band_rows(height, b, n);
        exr.push_back({file, row0, row1});
        const std::string preview = preview_path_for(file);
        if (fs::exists(preview)) png.push_back({preview, row0, row1});
        rays += std::stoull(image_attribute(file, "penumbra:rays", "0"));
        nonfinite += std::stoull(image_attribute(file, "penumbra:nonfinite_samples", "0"));
        spp = std::min<uint32_t>(spp,
                                 uint32_t(std::stoul(image_attribute(file, "penumbra:spp", "0"))));
        partial |= image_attribute(file, "penumbra:partial", "0") == "1";
        r.seconds += bands[size_t(b)].results[0].seconds;
        r.peak_memory = std::max(r.peak_memory, bands[size_t(b)].results[0].peak_memory);
    }
    // The header as one machine writes it: these are the only values that differ by band.
    HeaderStrings header = {{"penumbra:rays", std::to_string(rays)},
                            {"penumbra:nonfinite_samples", std::to_string(nonfinite)},
                            {"penumbra:spp", std::to_string(spp)},
                            {"penumbra:partial", partial ? "1" : "0"}};
    MergedImage image(exr);
    const std::optional<ImageWarning> warning = merged_image_warning(job, image, exr[0].path);
    if (warning) {
        header.push_back({"penumbra:image_warning", warning->message});
        r.image_warning = warning->kind;
    }
    // The bands' previews show the film's estimate: a denoised image's is made anew.
    bool merge_previews = png.size() == exr.size();
    if (job.options.denoise) {
        const ColorPipeline color(job.options.color);
        const MergedDenoise denoised = denoise_merged(job, color, image, spp, r);
        header.insert(header.end(), denoised.attributes.begin(), denoised.attributes.end());
        image.write(r.output, header);
        if (denoised.preview.width > 0) {
            write_preview(preview_path_for(r.output), denoised.preview, color);
            merge_previews = false;
        }
    } else {
        image.write(r.output, header);
    }
    if (merge_previews) merge_bands(png, preview_path_for(r.output));
    if (warning) LOG_WARNING(r.output << ": " << warning->message);
    r.spp = spp;
    r.rays = rays;
    r.status = partial ? JobStatus::Partial : JobStatus::Ok;
    if (partial) {
        r.message = "partial: a band was stopped; submitting again continues it";
        return;
    }
    std::error_code ec;
    for (const BandFile& f : exr) fs::remove(f.path, ec);
    for (const BandFile& f : png) fs::remove(f.path, ec);
}

}  // namespace

int run_farm_merge(const std::string& job_file, double checkpoint_interval) {
    const FarmPlan plan = load_farm_plan(job_file, checkpoint_interval);
    const std::string dir = farm_dir(job_file);
    std::vector<JobResult> results(plan.jobs.size());
    std::vector<std::vector<TaskRecord>> bands(plan.jobs.size());
    for (size_t j = 0; j < plan.jobs.size(); ++j) {
        results[j].scene = plan.jobs[j].scene;
        results[j].frame = plan.jobs[j].options.timeline.frame.value_or(-1);
    }
    std::vector<std::string> problems(plan.jobs.size());
    auto problem = [&](size_t job, const std::string& what) {
        problems[job] += (problems[job].empty() ? "" : "; ") + what;
    };
    for (size_t i = 0; i < plan.items.size(); ++i) {
        const WorkItem& item = plan.items[i];
        const BatchJob& job = plan.jobs[item.job];
        const std::string where =
            item.band < 0 ? "" : band_name(item.band, job.options.bands) + ": ";
        const auto rec = read_task_record(task_record_path(dir, i));
        if (!rec || rec->results.empty()) {
            for (size_t k = 0; k < item.count; ++k)
                problem(item.job + k, where + "task " + std::to_string(i) +
                                          " left no result (killed? see " + dir + "/logs/)");
            continue;
        }
        if (item.band >= 0) {
            if (rec->results[0].status == JobStatus::Failed)
                problem(item.job, where + rec->results[0].message);
            bands[item.job].push_back(*rec);
            continue;
        }
        for (size_t k = 0; k < item.count; ++k) {
            const size_t j = item.job + k;
            if (k >= rec->results.size()) {
                problem(j, "task " + std::to_string(i) + " left no result for this frame");
                continue;
            }
            JobResult r = rec->results[k];
            r.scene = results[j].scene;
            r.frame = results[j].frame;
            if (r.status == JobStatus::Failed) problem(j, r.message);
            // A frame the task never started (it was stopped before) is not done.
            if (r.status == JobStatus::Skipped && !fs::exists(r.output))
                problem(j, "not rendered: " + r.message);
            results[j] = r;
        }
    }
    for (size_t j = 0; j < plan.jobs.size(); ++j) {
        JobResult& r = results[j];
        if (!problems[j].empty()) {
            r.status = JobStatus::Failed;
            r.message = problems[j];
            continue;
        }
        if (plan.jobs[j].options.bands <= 1) continue;
        try {
            merge_image(plan.jobs[j], bands[j], r);
        } catch (const std::exception& e) {
            r.status = JobStatus::Failed;
            r.message = std::string("merge: ") + e.what();
        }
    }
    const bool bad = std::any_of(results.begin(), results.end(), [](const JobResult& r) {
        return r.status == JobStatus::Failed || r.status == JobStatus::Partial;
    });
    const std::string summary = format_summary(results);
    write_text_file(dir + "/summary.txt", summary);
    write_text_file(dir + "/exit_status", bad ? "1\n" : "0\n");
    std::fputs(summary.c_str(), stdout);
    return bad ? 1 : 0;
}

}  // namespace penumbra
