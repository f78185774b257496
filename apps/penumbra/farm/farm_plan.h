// The farm's work, as plain data: a job file's images (scenes x frames) cut into work
// items (a whole image, or one row band of it), one Slurm array task each, and the
// records tasks leave for the merge. A pure function of the job file, so submit, every
// task and the merge compute the same list; submit also writes it down (plan.txt) and
// tasks refuse to run when the job file has changed since.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "apps/penumbra/batch.h"

namespace penumbra {

struct WorkItem {
    size_t job = 0;    // index into the batch (plan_batch)
    int band = -1;     // row band of the job's options.bands; -1: the whole image
    size_t count = 1;  // whole images: jobs [job, job + count), frames of one entry
};

// A job file's batch as the farm renders it: render's default options with the job file
// (so each image is the one `render --job JOB` writes), its jobs and work items.
struct FarmPlan {
    RenderCommandOptions options;
    std::vector<BatchJob> jobs;
    std::vector<WorkItem> items;
};
// Throws SceneError for a bad job file, before anything is submitted or rendered.
FarmPlan load_farm_plan(const std::string& job_file, double checkpoint_interval);

// Jobs in batch order; a job with bands > 1 gives one item per band, in row order; up to
// frames_per_task consecutive frames of one entry share an item.
std::vector<WorkItem> plan_work(const std::vector<BatchJob>& jobs);
// One line per item: "index job band/bands frame scene", for plan.txt and its check.
std::string plan_text(const std::vector<BatchJob>& jobs, const std::vector<WorkItem>& items);

// Slurm array index ranges [first, last] for n items when an array may hold at most
// max_array_size tasks (MaxArraySize: indices 0 .. MaxArraySize - 1).
std::vector<std::pair<size_t, size_t>> array_chunks(size_t n, size_t max_array_size);

// The folder of a job file's farm state: JOB.farm/ beside JOB.json (plan, logs, task
// records, summary).
std::string farm_dir(const std::string& job_file);
std::string task_record_path(const std::string& dir, size_t item);

// What a task leaves for the merge: its images' results and, for a band, its file (the
// band's rows follow from the file's height: band_rows).
struct TaskRecord {
    size_t item = 0;
    std::vector<JobResult> results;  // one per image of the item, in batch order
    int band = -1, bands = 1;
    std::string band_file;  // band_output_path of the image's output
    std::string host;
    int restarts = 0;  // SLURM_RESTART_COUNT: how often Slurm requeued the task
};
void write_task_record(const std::string& path, const TaskRecord& record);
// Nothing when the file is missing or unreadable (the task never finished).
std::optional<TaskRecord> read_task_record(const std::string& path);

}  // namespace penumbra
