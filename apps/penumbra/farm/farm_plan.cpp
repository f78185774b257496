#include "apps/penumbra/farm/farm_plan.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
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
            WorkItem* last = items.empty() ? nullptr : &items.back();
            const BatchJob* prev = last ? &jobs[last->job] : nullptr;
            if (last && last->band < 0 && prev->where == jobs[j].where &&
                prev->scene == jobs[j].scene && !prev->where.empty() &&
                last->count < size_t(std::max(1, jobs[j].options.frames_per_task))) {
                ++last->count;
                continue;
            }
            items.push_back({j, -1, 1});
            continue;
        }
        for (int b = 0; b < bands; ++b) items.push_back({j, b, 1});
    }
    return items;
}

std::string plan_text(const std::vector<BatchJob>& jobs, const std::vector<WorkItem>& items) {
    std::ostringstream out;
    for (size_t i = 0; i < items.size(); ++i) {
        const BatchJob& job = jobs[items[i].job];
        out << i << " job " << items[i].job;
        if (items[i].count > 1) out << "-" << items[i].job + items[i].count - 1;
        out << " band "
            << (items[i].band < 0
                    ? std::string("-")
                    : std::to_string(items[i].band + 1) + "/" + std::to_string(job.options.bands))
            << " frame "
            << (job.options.timeline.frame ? std::to_string(*job.options.timeline.frame) : "-");
        if (items[i].count > 1) {
            const BatchJob& last = jobs[items[i].job + items[i].count - 1];
            out << "-" << last.options.timeline.frame.value_or(-1);
        }
        out
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

namespace {

const char* const kStatus[] = {"ok", "partial", "failed", "skipped"};

nlohmann::json result_json(const JobResult& r) {
    return {{"scene", r.scene},     {"output", r.output},   {"message", r.message},
            {"frame", r.frame},     {"status", kStatus[int(r.status)]},
            {"seconds", r.seconds}, {"spp", r.spp},         {"rays", r.rays},
            {"peak_memory", r.peak_memory}};
}

JobResult result_from(const nlohmann::json& j) {
    JobResult r;
    r.scene = j.at("scene").get<std::string>();
    r.output = j.at("output").get<std::string>();
    r.message = j.at("message").get<std::string>();
    r.frame = j.at("frame").get<int>();
    const std::string status = j.at("status").get<std::string>();
    r.status = JobStatus::Failed;
    for (int s = 0; s < 4; ++s)
        if (status == kStatus[s]) r.status = JobStatus(s);
    r.seconds = j.at("seconds").get<double>();
    r.spp = j.at("spp").get<uint32_t>();
    r.rays = j.at("rays").get<uint64_t>();
    r.peak_memory = j.at("peak_memory").get<uint64_t>();
    return r;
}

}  // namespace

void write_task_record(const std::string& path, const TaskRecord& rec) {
    nlohmann::json images = nlohmann::json::array();
    for (const JobResult& r : rec.results) images.push_back(result_json(r));
    const nlohmann::json j = {{"item", rec.item},           {"images", images},
                              {"band", rec.band},           {"bands", rec.bands},
                              {"band_file", rec.band_file}, {"host", rec.host},
                              {"restarts", rec.restarts}};
    write_text_file(path, j.dump(1) + "\n");
}

std::optional<TaskRecord> read_task_record(const std::string& path) {
    std::ifstream in(path);
    if (!in) return std::nullopt;
    try {
        const nlohmann::json j = nlohmann::json::parse(in);
        TaskRecord rec;
        rec.item = j.at("item").get<size_t>();
        for (const nlohmann::json& r : j.at("images")) rec.results.push_back(result_from(r));
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
