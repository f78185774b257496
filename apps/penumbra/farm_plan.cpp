#include "apps/penumbra/farm_plan.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/atomic_file.h"

namespace penumbra {

namespace fs = std::filesystem;

FarmPlan load_farm_plan(const std::string& job_file, double checkpoint_interval) {
    FarmPlan plan;
    plan.options.job_file = job_file;
    plan.options.checkpoint_interval = checkpoint_interval;
    plan.jobs = plan_batch(plan.options);
    plan.items = plan_work(plan.jobs);
    return plan;
}

std::vector<WorkItem> plan_work(const std::vector<BatchJob>& jobs) {
    std::vector<WorkItem> items;
    for (size_t j = 0; j < jobs.size(); ++j) {
        const int bands = jobs[j].options.bands;
        if (bands <= 1) {
            items.push_back({j, -1});
            continue;
        }
        for (int b = 0; b < bands; ++b) items.push_back({j, b});
    }
    return items;
}

std::string plan_text(const std::vector<BatchJob>& jobs, const std::vector<WorkItem>& items) {
    std::ostringstream out;
    for (size_t i = 0; i < items.size(); ++i) {
        const BatchJob& job = jobs[items[i].job];
        out << i << " job " << items[i].job << " band "
            << (items[i].band < 0 ? std::string("-")
                                  : std::to_string(items[i].band + 1) + "/" +
                                        std::to_string(job.options.bands))
            << " frame "
            << (job.options.timeline.frame ? std::to_string(*job.options.timeline.frame) : "-")
            << " " << job.scene << "\n";
    }
    return out.str();
}

std::vector<std::pair<size_t, size_t>> array_chunks(size_t n, size_t max_array_size) {
    std::vector<std::pair<size_t, size_t>> chunks;
    const size_t size = std::max<size_t>(1, max_array_size);
    for (size_t first = 0; first < n; first += size)
        chunks.push_back({first, std::min(n, first + size) - 1});
    return chunks;
}

std::string farm_dir(const std::string& job_file) {
    const fs::path p = fs::absolute(job_file).lexically_normal();
    return (p.parent_path() / (p.stem().string() + ".farm")).string();
}

std::string task_record_path(const std::string& dir, size_t item) {
    char name[40];
    std::snprintf(name, sizeof name, "item-%06zu.json", item);
    return (fs::path(dir) / "results" / name).string();
}

void write_task_record(const std::string& path, const TaskRecord& rec) {
    static const char* const kStatus[] = {"ok", "partial", "failed", "skipped"};
    const JobResult& r = rec.result;
    const nlohmann::json j = {
        {"item", rec.item},       {"scene", r.scene},        {"output", r.output},
        {"message", r.message},   {"frame", r.frame},        {"status", kStatus[int(r.status)]},
        {"seconds", r.seconds},   {"spp", r.spp},            {"rays", r.rays},
        {"peak_memory", r.peak_memory}, {"band", rec.band}, {"bands", rec.bands},
        {"band_file", rec.band_file},
        {"host", rec.host},       {"restarts", rec.restarts}};
    write_text_file(path, j.dump(1) + "\n");
}

std::optional<TaskRecord> read_task_record(const std::string& path) {
    std::ifstream in(path);
    if (!in) return std::nullopt;
    try {
        const nlohmann::json j = nlohmann::json::parse(in);
        TaskRecord rec;
        JobResult& r = rec.result;
        rec.item = j.at("item").get<size_t>();
        r.scene = j.at("scene").get<std::string>();
        r.output = j.at("output").get<std::string>();
        r.message = j.at("message").get<std::string>();
        r.frame = j.at("frame").get<int>();
        const std::string status = j.at("status").get<std::string>();
        r.status = status == "ok"        ? JobStatus::Ok
                   : status == "partial" ? JobStatus::Partial
                   : status == "skipped" ? JobStatus::Skipped
                                         : JobStatus::Failed;
        r.seconds = j.at("seconds").get<double>();
        r.spp = j.at("spp").get<uint32_t>();
        r.rays = j.at("rays").get<uint64_t>();
        r.peak_memory = j.at("peak_memory").get<uint64_t>();
        rec.band = j.at("band").get<int>();
        rec.bands = j.at("bands").get<int>();
        rec.band_file = j.at("band_file").get<std::string>();
        rec.host = j.at("host").get<std::string>();
        rec.restarts = j.at("restarts").get<int>();
        return rec;
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

}  // namespace penumbra
