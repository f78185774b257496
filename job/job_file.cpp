#include "job/job_file.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <stdexcept>

#include "core/error.h"

namespace penumbra {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// Every key a defaults or jobs[] entry may hold.
const char* const kKeys[] = {"scene",
                             "camera",
                             "variant",
                             "integrator",
                             "strategy",
                             "sampler",
                             "filter",
                             "accel",
                             "output",
                             "out_dir",
                             "name",
                             "frames",
                             "width",
                             "height",
                             "max_depth",
                             "frame",
                             "spp",
                             "seed",
                             "time",
                             "time_limit",
                             "fps",
                             "shutter",
                             "shutter_open",
                             "shutter_close",
                             "ocio_config",
                             "working_space",
                             "output_colorspace",
                             "display",
                             "view",
                             "look",
                             "aov",
                             "half",
                             "compression",
                             "light_units",
                             "default_light",
                             "no_file_lights",
                             "exposure",
                             "strict",
                             "max_texture_pixels",
                             "target_error",
                             "adaptive_min_spp",
                             "clamp_direct",
                             "clamp_indirect",
                             "regularize",
                             "bands",
                             "frames_per_task",
                             "light_sampler",
                             "triangle_sampling",
                             "env_sampling",
                             "denoise"};

// Reads one entry's keys into settings; `where` prefixes every message.
class SettingsReader {
public:
    SettingsReader(const json& object, std::string where, const fs::path& base)
        : m_object(object), m_where(std::move(where)), m_base(base) {}

    void read(JobSettings& s) const {
        check_keys();
        read_names(s);
        read_counts(s);
        read_timing(s);
        read_colour(s);
        read_lighting(s);
        read_quality(s);
    }

    [[noreturn]] void fail(const std::string& key, const std::string& what) const {
        throw SceneError(m_where + "." + key + ": " + what);
    }

private:
    void check_keys() const {
        for (const auto& [key, value] : m_object.items()) {
            bool known = false;
            for (const char* k : kKeys) known = known || key == k;
            if (!known) {
                std::string list;
                for (const char* k : kKeys) list += (list.empty() ? "" : ", ") + std::string(k);
                fail(key, "unknown key (expected one of: " + list + ")");
            }
        }
    }

    // Strings and paths: what to render, how, and where the output goes.
    void read_names(JobSettings& s) const {
        text("camera", s.camera);
        text("variant", s.variant);
        text("integrator", s.integrator);
        text("strategy", s.strategy);
        text("sampler", s.sampler);
        text("filter", s.filter);
        text("accel", s.accel);
        path("output", s.output);
        path("out_dir", s.out_dir);
        text("name", s.name);
        text("frames", s.frames);
        if (s.frames) try {
                parse_frame_list(*s.frames);
            } catch (const std::invalid_argument& e) {
                fail("frames", e.what());
            }
    }

    // Image size, depth, frame and task counts, samples and seed.
    void read_counts(JobSettings& s) const {
        integer("width", s.width, 1, 1 << 15);
        integer("height", s.height, 1, 1 << 15);
        integer("max_depth", s.max_depth, 0, 1024);
        integer("frame", s.frame, 0, 1 << 30);
        integer("bands", s.bands, 1, 4096);
        integer("frames_per_task", s.frames_per_task, 1, 100000);
        std::optional<int> spp;
        integer("spp", spp, 1, 1 << 24);
        if (spp) s.spp = static_cast<uint32_t>(*spp);
        if (m_object.contains("seed")) {
            const json& v = m_object["seed"];
            if (!v.is_number_unsigned()) fail("seed", "expected a non-negative integer");
            s.seed = v.get<uint64_t>();
        }
    }

    // Scene time, time limit and shutter.
    void read_timing(JobSettings& s) const {
        number("time", s.time, false);
        number("time_limit", s.time_limit, true);
        number("fps", s.fps, true);
        number("shutter_open", s.shutter_open, false);
        number("shutter_close", s.shutter_close, false);
        number("shutter", s.shutter, false);
        if (s.shutter && !(*s.shutter >= 0 && *s.shutter <= 1))
            fail("shutter", "expected a fraction of a frame in [0, 1]");
    }

    // Colour management and output encoding.
    void read_colour(JobSettings& s) const {
        // "builtin" names the built-in config, not a file next to the job file.
        if (m_object.contains("ocio_config") && m_object["ocio_config"] == "builtin")
            text("ocio_config", s.ocio_config);
        else
            path("ocio_config", s.ocio_config);
        text("working_space", s.working_space);
        text("output_colorspace", s.output_colorspace);
        text("display", s.display);
        text("view", s.view);
        text("look", s.look);
        text("aov", s.aov);
        text("compression", s.compression);
        boolean("half", s.half);
    }

    // Light units, default light, light sampling and exposure.
    void read_lighting(JobSettings& s) const {
        choice("light_units", s.light_units, {"photometric", "radiometric"});
        choice("default_light", s.default_light, {"auto", "on", "off"});
        boolean("no_file_lights", s.no_file_lights);
        choice("light_sampler", s.light_sampler, {"uniform", "power", "bvh", "auto"});
        choice("triangle_sampling", s.triangle_sampling, {"area", "solid-angle"});
        choice("env_sampling", s.env_sampling, {"auto", "full", "compensated"});
        number("exposure", s.exposure, false);
        if (s.exposure && std::abs(*s.exposure) > 64)
            fail("exposure", "expected stops in [-64, 64]");
    }

    // Strictness, denoising, adaptive sampling, clamping and texture limits.
    void read_quality(JobSettings& s) const {
        boolean("strict", s.strict);
        boolean("denoise", s.denoise);
        number("target_error", s.target_error, true);
        integer("adaptive_min_spp", s.adaptive_min_spp, 0, 1 << 24);
        number("clamp_direct", s.clamp_direct, true);
        number("clamp_indirect", s.clamp_indirect, true);
        number("regularize", s.regularize, false);
        if (s.regularize && !(*s.regularize >= 0 && *s.regularize <= 1))
            fail("regularize", "expected a roughness in [0, 1]");
        if (m_object.contains("max_texture_pixels")) {
            const json& v = m_object["max_texture_pixels"];
            if (!v.is_number_unsigned() || v.get<uint64_t>() < 1)
                fail("max_texture_pixels", "expected a positive integer");
            s.max_texture_pixels = v.get<uint64_t>();
        }
    }

    void text(const char* key, std::optional<std::string>& out) const {
        if (!m_object.contains(key)) return;
        const json& v = m_object[key];
        if (!v.is_string() || v.get<std::string>().empty())
            fail(key, "expected a non-empty string");
        out = v.get<std::string>();
    }
    void choice(const char* key, std::optional<std::string>& out,
                std::initializer_list<const char*> allowed) const {
        text(key, out);
        if (!out) return;
        std::string list;
        for (const char* a : allowed) {
            if (*out == a) return;
            list += (list.empty() ? "" : ", ") + std::string(a);
        }
        fail(key, "'" + *out + "' is not one of: " + list);
    }
    void path(const char* key, std::optional<std::string>& out) const {
        text(key, out);
        if (out && fs::path(*out).is_relative()) out = (m_base / *out).lexically_normal().string();
    }
    void boolean(const char* key, std::optional<bool>& out) const {
        if (!m_object.contains(key)) return;
        if (!m_object[key].is_boolean()) fail(key, "expected true or false");
        out = m_object[key].get<bool>();
    }
    void integer(const char* key, std::optional<int>& out, int lo, int hi) const {
        if (!m_object.contains(key)) return;
        const json& v = m_object[key];
        if (!v.is_number_integer() || v.get<int64_t>() < lo || v.get<int64_t>() > hi)
            fail(key, "expected an integer in [" + std::to_string(lo) + ", " +
                          std::to_string(hi) + "]");
        out = static_cast<int>(v.get<int64_t>());
    }
    void number(const char* key, std::optional<double>& out, bool positive) const {
        if (!m_object.contains(key)) return;
        const json& v = m_object[key];
        if (!v.is_number() || !std::isfinite(v.get<double>()) ||
            (positive && !(v.get<double>() > 0)))
            fail(key, positive ? "expected a positive number" : "expected a finite number");
        out = v.get<double>();
    }

    const json& m_object;
    std::string m_where;
    fs::path m_base;
};

}  // namespace

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
        SettingsReader reader(d, path + ": defaults", base);
        if (d.contains("scene")) reader.fail("scene", "belongs in a jobs[] entry");
        reader.read(file.defaults);
    }
    if (!root.contains("jobs") || !root["jobs"].is_array() || root["jobs"].empty())
        throw SceneError(path + ": jobs: expected a non-empty array of {\"scene\": ...}");
    const json& jobs = root["jobs"];
    for (size_t i = 0; i < jobs.size(); ++i) {
        JobEntry entry;
        entry.where = path + ": jobs[" + std::to_string(i) + "]";
        if (!jobs[i].is_object()) throw SceneError(entry.where + ": expected an object");
        const SettingsReader reader(jobs[i], entry.where, base);
        std::optional<std::string> scene;
        if (jobs[i].contains("scene") && jobs[i]["scene"].is_string())
            scene = jobs[i]["scene"].get<std::string>();
        if (!scene || scene->empty()) reader.fail("scene", "expected the scene file's path");
        entry.scene = fs::path(*scene).is_relative()
                          ? (base / *scene).lexically_normal().string()
                          : *scene;
        reader.read(entry.settings);
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
