#include "job/job_file.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "core/error.h"
#include "job/option_table.h"

namespace penumbra {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// A value of a JSON type the option's kind takes, as the option's text.
std::string kind_text(const OptionDecl& d, const json& v) {
    switch (d.kind) {
        case OptionKind::Flag:
            if (!v.is_boolean()) throw std::invalid_argument("expected true or false");
            return v.get<bool>() ? "1" : "0";
        case OptionKind::Integer:
            if (!v.is_number_integer()) throw std::invalid_argument("expected an integer");
            return v.dump();
        case OptionKind::Number:
            if (!v.is_number()) throw std::invalid_argument("expected a number");
            return v.dump();
        case OptionKind::Numbers: {
            if (!v.is_array() || int(v.size()) != d.count)
                throw std::invalid_argument("expected an array of " + std::to_string(d.count) +
                                            " numbers");
            std::string text;
            for (const json& x : v) {
                if (!x.is_number()) throw std::invalid_argument("expected numbers");
                text += (text.empty() ? "" : " ") + x.dump();
            }
            return text;
        }
        case OptionKind::Text:
        case OptionKind::Path:
        case OptionKind::Choice:
            if (!v.is_string() || v.get<std::string>().empty())
                throw std::invalid_argument("expected a non-empty string");
            return v.get<std::string>();
    }
    throw std::logic_error("an option kind without a JSON type");
}

std::string known_keys() {
    std::string list = "scene";
    for (const OptionDecl& d : render_option_table())
        if (!d.job_key.empty()) list += ", " + d.job_key;
    return list;
}

// Reads one entry's keys (all but "scene") into settings; `where` prefixes every message.
JobSettings read_settings(const json& object, const std::string& where, const fs::path& base) {
    JobSettings settings;
    RenderCommandOptions scratch;  // checks each value as the command line would
    for (const auto& [key, value] : object.items()) {
        if (key == "scene") continue;
        const OptionDecl* d = find_option(key);
        if (!d || d->job_key != key)
            throw SceneError(where + "." + key + ": unknown key (expected one of: " +
                             known_keys() + ")");
        try {
            const std::string text = job_value_text(*d, value, base.string());
            d->set(scratch, text);
            settings.push_back({d, text});
        } catch (const std::invalid_argument& e) {
            throw SceneError(where + "." + key + ": " + e.what());
        }
    }
    return settings;
}

}  // namespace

std::string job_value_text(const OptionDecl& d, const json& value, const std::string& base) {
    std::string text = kind_text(d, value);
    // "builtin" (--ocio-config) names the built-in config, not a file.
    const bool is_choice =
        std::find(d.choices.begin(), d.choices.end(), text) != d.choices.end();
    const bool is_keyword = !d.keyword_prefix.empty() && text.rfind(d.keyword_prefix, 0) == 0;
    if (d.kind == OptionKind::Path && !is_choice && !is_keyword && fs::path(text).is_relative())
        text = (fs::path(base) / text).lexically_normal().string();
    return text;
}

JobFile parse_job_file(const std::string& text, const std::string& path) {
    json root;
    try {
        root = json::parse(text);
    } catch (const json::parse_error& e) {
        throw SceneError(path + ": not valid JSON: " + e.what());
    }
    if (!root.is_object()) throw SceneError(path + ": expected a JSON object");
    for (const auto& [key, value] : root.items())
        if (key != "defaults" && key != "jobs")
            throw SceneError(path + ": unknown key '" + key + "' (expected defaults, jobs)");
    const fs::path base = fs::path(path).parent_path();
    JobFile file;
    if (root.contains("defaults")) {
        const json& d = root["defaults"];
        if (!d.is_object()) throw SceneError(path + ": defaults: expected an object");
        if (d.contains("scene"))
            throw SceneError(path + ": defaults.scene: belongs in a jobs[] entry");
        file.defaults = read_settings(d, path + ": defaults", base);
    }
    if (!root.contains("jobs") || !root["jobs"].is_array() || root["jobs"].empty())
        throw SceneError(path + ": jobs: expected a non-empty array of {\"scene\": ...}");
    const json& jobs = root["jobs"];
    for (size_t i = 0; i < jobs.size(); ++i) {
        JobEntry entry;
        entry.where = path + ": jobs[" + std::to_string(i) + "]";
        if (!jobs[i].is_object()) throw SceneError(entry.where + ": expected an object");
        std::string scene;
        if (jobs[i].contains("scene") && jobs[i]["scene"].is_string())
            scene = jobs[i]["scene"].get<std::string>();
        if (scene.empty())
            throw SceneError(entry.where + ".scene: expected the scene file's path");
        entry.scene =
            fs::path(scene).is_relative() ? (base / scene).lexically_normal().string() : scene;
        entry.settings = read_settings(jobs[i], entry.where, base);
        file.jobs.push_back(std::move(entry));
    }
    return file;
}

JobFile read_job_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SceneError(path + ": cannot open the job file");
    std::ostringstream text;
    text << in.rdbuf();
    return parse_job_file(text.str(), path);
}

std::vector<int> parse_frame_list(const std::string& spec) {
    // A frame list longer than this is almost certainly a typo ("1-100000").
    constexpr size_t kMaxFrames = 100000;
    auto bad = [&](const std::string& why) {
        return std::invalid_argument("frames '" + spec + "': " + why +
                                     " (expected e.g. 12, 1-48, 1-48:2 or 1,5,10-12)");
    };
    auto number = [&](const std::string& t) {
        if (t.empty() || t.find_first_not_of("0123456789") != std::string::npos || t.size() > 9)
            throw bad("'" + t + "' is not a frame number");
        return std::stoi(t);
    };
    std::vector<int> frames;
    std::stringstream items(spec);
    std::string item;
    while (std::getline(items, item, ',')) {
        std::string range = item;
        int step = 1;
        if (const size_t colon = item.find(':'); colon != std::string::npos) {
            range = item.substr(0, colon);
            step = number(item.substr(colon + 1));
            if (step < 1) throw bad("the step must be at least 1");
        }
        const size_t dash = range.find('-');
        const int first = number(range.substr(0, dash));
        const int last = dash == std::string::npos ? first : number(range.substr(dash + 1));
        if (last < first) throw bad(std::to_string(last) + " comes before " + std::to_string(first));
        for (int f = first; f <= last; f += step) {
            frames.push_back(f);
            if (frames.size() > kMaxFrames) throw bad("more than 100000 frames");
        }
    }
    if (frames.empty()) throw bad("no frames");
    return frames;
}

}  // namespace penumbra
