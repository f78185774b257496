// Batch job files: JSON with global defaults and one entry per scene that overrides
// them, validated like scene files (errors name the file and the element). Also the
// frame-list syntax shared by --frames and the job file's "frames".
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace penumbra {

struct OptionDecl;

// One key of a defaults or jobs[] entry: a declared render option (job/option_table.h)
// and its value as the option's text. Relative paths are already resolved against the
// job file's folder.
struct JobSetting {
    const OptionDecl* option;
    std::string text;
};
// Unset keys inherit (command line < defaults < entry).
using JobSettings = std::vector<JobSetting>;

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

// One key's JSON value as the option's text (the text `set` reads), checked against the
// option's kind (a flag takes true or false, Numbers an array of `count` numbers, ...), a
// relative Path resolved against `base`. Job files and the Python module's keyword
// arguments both go through it. Throws std::invalid_argument saying what is wrong.
std::string job_value_text(const OptionDecl& d, const nlohmann::json& value,
                           const std::string& base);

// "12", "1-48", "1-48:4" (every 4th), or a comma-separated list of those, in order.
// Throws std::invalid_argument with the reason.
std::vector<int> parse_frame_list(const std::string& spec);

}  // namespace penumbra
