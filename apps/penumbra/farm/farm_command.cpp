#include "apps/penumbra/farm/farm_command.h"

#include <CLI/CLI.hpp>

#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "apps/penumbra/batch.h"
#include "apps/penumbra/farm/farm_merge.h"
#include "apps/penumbra/farm/farm_plan.h"
#include "apps/penumbra/farm/farm_slurm.h"
#include "core/error.h"
#include "io/atomic_file.h"

namespace penumbra {

namespace fs = std::filesystem;

CLI::App* add_farm_command(CLI::App& app, FarmOptions& o) {
    CLI::App* farm = app.add_subcommand(
        "farm", "Render a job file on a Slurm cluster: one array task per image or band");
    farm->require_subcommand(1);
    CLI::App* submit = farm->add_subcommand(
        "submit", "Submit the job file's images as a Slurm array job plus a merge job");
    submit->add_option("job", o.job_file, "JSON job file (as render --job)")
        ->required()
        ->check(CLI::ExistingFile);
    submit->add_option("--partition", o.partition, "Slurm partition");
    submit->add_option("--cpus-per-task", o.cpus_per_task, "CPUs per task (sbatch -c)")
        ->check(CLI::PositiveNumber);
    submit
        ->add_option("--max-running", o.max_running,
                     "At most this many tasks at once (the array's %K)")
        ->check(CLI::PositiveNumber);
    submit->add_option("--sbatch-args", o.sbatch_args,
                       "More sbatch options for every job, e.g. \"--time=1:00:00 --mem=8G\"");
    submit
        ->add_option("--checkpoint-interval", o.checkpoint_interval,
                     "Seconds between a task's checkpoints (a requeued task continues "
                     "from its last one)")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    submit->add_flag("--wait", o.wait,
                     "Wait for the merge, print the summary; exit 1 if an image failed");
    CLI::App* status = farm->add_subcommand("status", "Show a submitted job file's progress");
    status->add_option("job", o.job_file, "JSON job file")->required();
    CLI::App* task = farm->add_subcommand("task", "Render one work item (run by Slurm)");
    task->add_option("job", o.job_file, "JSON job file")->required()->check(CLI::ExistingFile);
    task->add_option("--offset", o.offset, "First work item of this array");
    task->add_option("--index", o.index, "Array index ($SLURM_ARRAY_TASK_ID)")->required();
    task->add_option("--checkpoint-interval", o.checkpoint_interval, "Seconds")
        ->check(CLI::NonNegativeNumber);
    CLI::App* merge =
        farm->add_subcommand("merge", "Assemble bands and write the summary (run by Slurm)");
    merge->add_option("job", o.job_file, "JSON job file")->required()->check(CLI::ExistingFile);
    return farm;
}

namespace {

// The CPUs Slurm gave this task; outside Slurm, those this process may run on.
int task_cpus() {
    for (const char* var : {"SLURM_CPUS_PER_TASK", "SLURM_CPUS_ON_NODE"})
        if (const char* v = std::getenv(var); v && std::atoi(v) > 0) return std::atoi(v);
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0) return CPU_COUNT(&set);
    return 0;
}

std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// Single-quoted for /bin/sh.
std::string quoted(const std::string& s) {
    if (s.find('\'') != std::string::npos)
        throw SceneError(s + ": a path with a single quote cannot go into the task script");
    return "'" + s + "'";
}

std::string self_path() {
    std::error_code ec;
    const fs::path p = fs::read_symlink("/proc/self/exe", ec);
    if (ec) throw SceneError("cannot find the penumbra executable (/proc/self/exe)");
    return p.string();
}

int run_submit(const FarmOptions& o) {
    const FarmPlan plan = load_farm_plan(o.job_file, o.checkpoint_interval);
    const std::string dir = farm_dir(o.job_file);
    std::error_code ec;
    fs::remove_all(fs::path(dir) / "results", ec);  // records of an earlier submit
    fs::remove(fs::path(dir) / "summary.txt", ec);
    fs::remove(fs::path(dir) / "exit_status", ec);
    fs::create_directories(fs::path(dir) / "logs");
    write_text_file(dir + "/plan.txt", plan_text(plan.jobs, plan.items));

    const std::string bin = quoted(self_path());
    // The job file as given: tasks run in this folder (--chdir), so scene paths, outputs and
    // their metadata are those of `render --job` run here.
    const std::string job = quoted(o.job_file);
    char interval[32];
    std::snprintf(interval, sizeof interval, "%g", o.checkpoint_interval);
    // exec: the task is the batch step's process, so Slurm's SIGTERM reaches it directly.
    write_text_file(dir + "/task.sh",
                    "#!/bin/sh\n# One work item of " + job + " (penumbra farm submit).\nexec " +
                        bin + " farm task " + job + " --offset \"$1\" --index " +
                        "\"$SLURM_ARRAY_TASK_ID\" --checkpoint-interval " + interval + "\n");
    write_text_file(dir + "/merge.sh", "#!/bin/sh\n# Bands and summary of " + job +
                                           " (penumbra farm submit).\nexec " + bin +
                                           " farm merge " + job + "\n");

    std::vector<std::string> common = {"--chdir=" + fs::current_path().string()};
    if (!o.partition.empty()) common.push_back("--partition=" + o.partition);
    const std::vector<std::string> extra = split_arguments(o.sbatch_args);
    const std::string name = fs::path(o.job_file).stem().string();

    std::vector<std::string> ids;
    std::string jobs_txt;
    for (const auto& [first, last] : array_chunks(plan.items.size(), max_array_size())) {
        std::vector<std::string> args = common;
        std::string array = "--array=0-" + std::to_string(last - first);
        if (o.max_running > 0) array += "%" + std::to_string(o.max_running);
        args.push_back(array);
        args.push_back("--job-name=penumbra:" + name);
        // Requeueable: after preemption or a node failure the task runs again and
        // continues from its checkpoint. SIGTERM 2 minutes before a time limit gives it
        // time to end its pass and write one.
        args.push_back("--requeue");
        args.push_back("--signal=B:TERM@120");
        args.push_back("--open-mode=append");
        args.push_back("--output=" + dir + "/logs/task-%A_%a.log");
        if (o.cpus_per_task > 0)
            args.push_back("--cpus-per-task=" + std::to_string(o.cpus_per_task));
        args.insert(args.end(), extra.begin(), extra.end());
        const std::string id = sbatch(args, dir + "/task.sh", {std::to_string(first)});
        ids.push_back(id);
        jobs_txt += "array " + id + " " + std::to_string(first) + "-" + std::to_string(last) + "\n";
    }
    std::string dependency = "--dependency=afterany";
    for (const std::string& id : ids) dependency += ":" + id;
    // A merge that denoises a banded image runs the denoiser on all of it: it gets the
    // tasks' CPUs. Otherwise it only copies rows.
    const bool merge_denoises =
        std::any_of(plan.jobs.begin(), plan.jobs.end(), [](const BatchJob& j) {
            return j.options.denoise && j.options.bands > 1;
        });
    const int merge_cpus = merge_denoises && o.cpus_per_task > 0 ? o.cpus_per_task : 1;
    std::vector<std::string> args = common;
    args.insert(args.end(), {dependency, "--job-name=penumbra-merge:" + name,
                             "--output=" + dir + "/logs/merge-%j.log",
                             "--cpus-per-task=" + std::to_string(merge_cpus)});
    args.insert(args.end(), extra.begin(), extra.end());
    const std::string merge_id = sbatch(args, dir + "/merge.sh");
    jobs_txt += "merge " + merge_id + "\n";
    write_text_file(dir + "/jobs.txt", jobs_txt);
    std::printf("%zu work items (%zu images) submitted: array job%s", plan.items.size(),
                plan.jobs.size(), ids.size() > 1 ? "s" : "");
    for (const std::string& id : ids) std::printf(" %s", id.c_str());
    std::printf(", merge job %s; state in %s\n", merge_id.c_str(), dir.c_str());
    std::fflush(stdout);
    if (!o.wait) return 0;

    while (job_in_queue(merge_id)) std::this_thread::sleep_for(std::chrono::seconds(1));
    const std::string summary = read_text(dir + "/summary.txt");
    const std::string status = read_text(dir + "/exit_status");
    if (summary.empty() || status.empty())
        throw SceneError("the merge job " + merge_id + " ended without a summary; see " + dir +
                         "/logs/merge-" + merge_id + ".log");
    std::fputs(summary.c_str(), stdout);
    return std::atoi(status.c_str());
}

int run_status(const FarmOptions& o) {
    const std::string dir = farm_dir(o.job_file);
    const std::string jobs_txt = read_text(dir + "/jobs.txt");
    if (jobs_txt.empty())
        throw SceneError(o.job_file + ": not submitted (no " + dir + "/jobs.txt)");
    std::vector<std::string> ids;
    std::istringstream lines(jobs_txt);
    for (std::string kind, id, rest; lines >> kind >> id;) {
        ids.push_back(id);
        if (kind == "array") lines >> rest;
    }
    std::fputs(queue_report(ids).c_str(), stdout);
    const FarmPlan plan = load_farm_plan(o.job_file, o.checkpoint_interval);
    size_t done = 0, failed = 0;
    for (size_t i = 0; i < plan.items.size(); ++i) {
        const auto rec = read_task_record(task_record_path(dir, i));
        if (!rec) continue;
        ++done;
        for (const JobResult& r : rec->results) failed += r.status == JobStatus::Failed;
    }
    std::printf("%zu of %zu work items finished (%zu failed), %zu images\n", done,
                plan.items.size(), failed, plan.jobs.size());
    const std::string summary = read_text(dir + "/summary.txt");
    if (!summary.empty()) std::printf("merged:\n%s", summary.c_str());
    return 0;
}

int run_task(const FarmOptions& o) {
    const size_t item = o.offset + o.index;
    const std::string dir = farm_dir(o.job_file);
    TaskRecord rec;
    rec.item = item;
    char host[256] = "";
    gethostname(host, sizeof host - 1);
    rec.host = host;
    if (const char* r = std::getenv("SLURM_RESTART_COUNT")) rec.restarts = std::atoi(r);
    int status = 1;
    try {
        FarmPlan plan = load_farm_plan(o.job_file, o.checkpoint_interval);
        plan.options.threads = task_cpus();
        // The plan submit wrote down must be the one computed now.
        const std::string submitted = read_text(dir + "/plan.txt");
        if (!submitted.empty() && submitted != plan_text(plan.jobs, plan.items))
            throw SceneError(o.job_file +
                             ": changed since it was submitted (its work items "
                             "differ from " +
                             dir + "/plan.txt); submit it again");
        if (item >= plan.items.size())
            throw SceneError(o.job_file + ": work item " + std::to_string(item) +
                             " does not exist (the plan has " + std::to_string(plan.items.size()) +
                             ")");
        const WorkItem& work = plan.items[item];
        std::vector<BatchJob> jobs(plan.jobs.begin() + long(work.job),
                                   plan.jobs.begin() + long(work.job + work.count));
        for (BatchJob& job : jobs) job.band = work.band;
        status = run_render_jobs(jobs, plan.options, rec.results);
        rec.band = work.band;
        rec.bands = jobs[0].options.bands;
        if (work.band >= 0 && !rec.results.at(0).output.empty())
            rec.band_file = band_output_path(rec.results[0].output, work.band, rec.bands);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        JobResult failed;
        failed.status = JobStatus::Failed;
        failed.message = e.what();
        rec.results = {failed};
    }
    write_task_record(task_record_path(dir, item), rec);
    return status;
}

}  // namespace

int run_farm_command(const CLI::App& farm, const FarmOptions& o) {
    if (farm.got_subcommand("submit")) return run_submit(o);
    if (farm.got_subcommand("status")) return run_status(o);
    if (farm.got_subcommand("task")) return run_task(o);
    if (farm.got_subcommand("merge")) return run_farm_merge(o.job_file, o.checkpoint_interval);
    return 1;
}

}  // namespace penumbra
