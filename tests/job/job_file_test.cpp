// Job files: defaults and per-scene overrides, paths relative to the file, and errors
// that name the file and the element; and the frame-list syntax.
#include "job/job_file.h"
#include "job/option_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "core/error.h"

namespace penumbra {
namespace {

// A key's value as the job file gave it (the option's text); nullopt when unset.
std::optional<std::string> value(const JobSettings& settings, const std::string& key) {
    for (const JobSetting& s : settings)
        if (s.option->job_key == key) return s.text;
    return std::nullopt;
}

double number(const JobSettings& settings, const std::string& key) {
    const std::optional<std::string> v = value(settings, key);
    return v ? std::stod(*v) : std::nan("");
}

TEST(JobFile, ReadsDefaultsAndEntriesWithPathsRelativeToTheFile) {
    const JobFile f = parse_job_file(R"({
        "defaults": {"spp": 64, "width": 320, "integrator": "path", "out_dir": "renders"},
        "jobs": [
            {"scene": "a.gltf"},
            {"scene": "/abs/b.glb", "camera": "side", "height": 200, "seed": 7, "time": 1.5,
             "output": "x/b.exr", "frames": "1-3", "fps": 30, "time_limit": 60}
        ]})",
                                     "/work/jobs/batch.json");
    EXPECT_EQ(number(f.defaults, "spp"), 64);
    EXPECT_EQ(number(f.defaults, "width"), 320);
    EXPECT_EQ(value(f.defaults, "integrator"), "path");
    EXPECT_EQ(value(f.defaults, "out_dir"), "/work/jobs/renders");
    ASSERT_EQ(f.jobs.size(), 2u);
    EXPECT_EQ(f.jobs[0].scene, "/work/jobs/a.gltf");
    EXPECT_FALSE(value(f.jobs[0].settings, "spp"));  // unset: inherits
    EXPECT_EQ(f.jobs[0].where, "/work/jobs/batch.json: jobs[0]");
    const JobSettings& b = f.jobs[1].settings;
    EXPECT_EQ(f.jobs[1].scene, "/abs/b.glb");
    EXPECT_EQ(value(b, "camera"), "side");
    EXPECT_EQ(number(b, "height"), 200);
    EXPECT_EQ(number(b, "seed"), 7);
    EXPECT_EQ(number(b, "time"), 1.5);
    EXPECT_EQ(value(b, "output"), "/work/jobs/x/b.exr");
    EXPECT_EQ(value(b, "frames"), "1-3");
    EXPECT_EQ(number(b, "fps"), 30.0);
    EXPECT_EQ(number(b, "time_limit"), 60.0);
}

TEST(JobFile, ErrorsNameTheFileAndElement) {
    auto message = [](const std::string& text) {
        try {
            parse_job_file(text, "j.json");
        } catch (const SceneError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message("{\"jobs\": [").rfind("j.json: not valid JSON", 0), 0u);
    EXPECT_EQ(message("{}"), "j.json: jobs: expected a non-empty array of {\"scene\": ...}");
    EXPECT_EQ(message(R"({"jobs": [{"spp": 4}]})"),
              "j.json: jobs[0].scene: expected the scene file's path");
    EXPECT_EQ(message(R"({"jobs": [{"scene": "a.gltf", "spp": 0}]})"),
              "j.json: jobs[0].spp: 0 is not in [1, 16777216]");
    EXPECT_EQ(message(R"({"jobs": [{"scene": "a.gltf", "width": 1.5}]})"),
              "j.json: jobs[0].width: expected an integer");
    EXPECT_EQ(message(R"({"jobs": [{"scene": "a.gltf", "fps": -2}]})"),
              "j.json: jobs[0].fps: -2 is not above 0");
    EXPECT_EQ(message(R"({"jobs": [{"scene": "a.gltf", "seed": -1}]})"),
              "j.json: jobs[0].seed: '-1' is negative");
    EXPECT_EQ(message(R"({"defaults": {"camera": 3}, "jobs": [{"scene": "a.gltf"}]})"),
              "j.json: defaults.camera: expected a non-empty string");
    EXPECT_EQ(message(R"({"jobs": [{"scene": "a.gltf", "frames": "9-2"}]})")
                  .rfind("j.json: jobs[0].frames: frames '9-2': 2 comes before 9", 0),
              0u);
    EXPECT_NE(message(R"({"jobs": [{"scene": "a.gltf", "sp": 4}]})")
                  .find("j.json: jobs[0].sp: unknown key (expected one of: scene, output, out_dir, name"),
              std::string::npos);
    EXPECT_EQ(message(R"({"job": []})"), "j.json: unknown key 'job' (expected defaults, jobs)");
}

TEST(JobFile, ShutterKeys) {
    const JobFile f = parse_job_file(
        R"({"defaults": {"shutter": 0.5, "fps": 30},
            "jobs": [{"scene": "a.gltf", "shutter_open": 1.25, "shutter_close": 1.5}]})",
        "j.json");
    EXPECT_EQ(number(f.defaults, "shutter"), 0.5);
    EXPECT_EQ(number(f.jobs[0].settings, "shutter_open"), 1.25);
    EXPECT_EQ(number(f.jobs[0].settings, "shutter_close"), 1.5);
    try {
        parse_job_file(R"({"jobs": [{"scene": "a.gltf", "shutter": 2}]})", "j.json");
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "j.json: jobs[0].shutter: 2 is not in [0, 1]");
    }
}

TEST(JobFile, ColourAndOutputKeys) {
    const JobFile f = parse_job_file(
        R"({"defaults": {"ocio_config": "configs/studio.ocio", "view": "Raw", "half": true},
            "jobs": [{"scene": "a.gltf", "ocio_config": "builtin", "working_space": "ACEScg",
                      "output_colorspace": "ACES2065-1", "display": "sRGB", "look": "none",
                      "aov": "albedo,depth", "compression": "piz", "half": false}]})",
        "/jobs/j.json");
    // A config path is relative to the job file; "builtin" is a name, not a path.
    EXPECT_EQ(value(f.defaults, "ocio_config"), "/jobs/configs/studio.ocio");
    EXPECT_EQ(value(f.defaults, "view"), "Raw");
    EXPECT_EQ(value(f.defaults, "half"), "1");
    const JobSettings& s = f.jobs[0].settings;
    EXPECT_EQ(value(s, "ocio_config"), "builtin");
    EXPECT_EQ(value(s, "working_space"), "ACEScg");
    EXPECT_EQ(value(s, "output_colorspace"), "ACES2065-1");
    EXPECT_EQ(value(s, "display"), "sRGB");
    EXPECT_EQ(value(s, "look"), "none");
    EXPECT_EQ(value(s, "aov"), "albedo,depth");
    EXPECT_EQ(value(s, "compression"), "piz");
    EXPECT_EQ(value(s, "half"), "0");
    try {
        parse_job_file(R"({"jobs": [{"scene": "a.gltf", "half": "yes"}]})", "j.json");
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()), "j.json: jobs[0].half: expected true or false");
    }
}

TEST(JobFile, LightKeys) {
    const JobFile f = parse_job_file(
        R"({"defaults": {"light_units": "radiometric", "exposure": 1.5, "light_sampler": "power"},
            "jobs": [{"scene": "a.gltf", "default_light": "off", "exposure": -2,
                      "triangle_sampling": "area", "env_sampling": "full",
                      "no_file_lights": true}]})",
        "/jobs/j.json");
    EXPECT_EQ(value(f.defaults, "light_sampler"), "power");
    EXPECT_EQ(value(f.jobs[0].settings, "triangle_sampling"), "area");
    EXPECT_EQ(value(f.jobs[0].settings, "env_sampling"), "full");
    EXPECT_FALSE(value(f.defaults, "env_sampling"));
    EXPECT_EQ(value(f.defaults, "light_units"), "radiometric");
    EXPECT_EQ(number(f.defaults, "exposure"), 1.5);
    EXPECT_FALSE(value(f.defaults, "default_light"));
    EXPECT_EQ(value(f.jobs[0].settings, "default_light"), "off");
    EXPECT_EQ(number(f.jobs[0].settings, "exposure"), -2.0);
    EXPECT_FALSE(value(f.jobs[0].settings, "light_units"));
    EXPECT_EQ(value(f.jobs[0].settings, "no_file_lights"), "1");
    EXPECT_FALSE(value(f.defaults, "no_file_lights"));
    const std::pair<const char*, const char*> bad[] = {
        {R"("light_units": "lumens")",
         "j.json: jobs[0].light_units: unknown light-units 'lumens' (expected one of: "
         "photometric, radiometric)"},
        {R"("default_light": true)", "j.json: jobs[0].default_light: expected a non-empty string"},
        {R"("default_light": "maybe")",
         "j.json: jobs[0].default_light: unknown default-light 'maybe' (expected one of: auto, "
         "on, off)"},
        {R"("exposure": "bright")", "j.json: jobs[0].exposure: expected a number"},
        {R"("no_file_lights": "yes")", "j.json: jobs[0].no_file_lights: expected true or false"},
        {R"("exposure": 100)", "j.json: jobs[0].exposure: 100 is not in [-64, 64]"},
        {R"("light_sampler": "tree")",
         "j.json: jobs[0].light_sampler: unknown light-sampler 'tree' (expected one of: "
         "uniform, power, bvh, auto)"},
        {R"("triangle_sampling": "sphere")",
         "j.json: jobs[0].triangle_sampling: unknown triangle-sampling 'sphere' (expected one "
         "of: area, solid-angle)"},
        {R"("env_sampling": "mis")",
         "j.json: jobs[0].env_sampling: unknown env-sampling 'mis' (expected one of: auto, "
         "full, compensated)"}};
    for (const auto& [member, message] : bad) {
        try {
            parse_job_file(std::string(R"({"jobs": [{"scene": "a.gltf", )") + member + "}]}",
                           "j.json");
            FAIL() << member;
        } catch (const SceneError& e) {
            EXPECT_EQ(std::string(e.what()), message);
        }
    }
}

TEST(JobFile, AdaptiveAndFireflyKeys) {
    const JobFile f = parse_job_file(
        R"({"defaults": {"target_error": 0.05, "adaptive_min_spp": 32},
            "jobs": [{"scene": "a.gltf", "clamp_direct": 20, "clamp_indirect": 10,
                      "regularize": 0.3}]})",
        "/jobs/j.json");
    EXPECT_EQ(number(f.defaults, "target_error"), 0.05);
    EXPECT_EQ(number(f.defaults, "adaptive_min_spp"), 32);
    EXPECT_FALSE(value(f.defaults, "clamp_indirect"));
    EXPECT_EQ(number(f.jobs[0].settings, "clamp_direct"), 20.0);
    EXPECT_EQ(number(f.jobs[0].settings, "clamp_indirect"), 10.0);
    EXPECT_EQ(number(f.jobs[0].settings, "regularize"), 0.3);
    EXPECT_FALSE(value(f.jobs[0].settings, "target_error"));
    const std::pair<const char*, const char*> bad[] = {
        {R"("target_error": 0)", "j.json: jobs[0].target_error: 0 is not above 0"},
        {R"("target_error": "low")", "j.json: jobs[0].target_error: expected a number"},
        {R"("clamp_indirect": -1)",
         "j.json: jobs[0].clamp_indirect: -1 is not at least 0"},
        {R"("regularize": 2)", "j.json: jobs[0].regularize: 2 is not in [0, 1]"}};
    for (const auto& [member, message] : bad) {
        try {
            parse_job_file(std::string(R"({"jobs": [{"scene": "a.gltf", )") + member + "}]}",
                           "j.json");
            FAIL() << member;
        } catch (const SceneError& e) {
            EXPECT_EQ(std::string(e.what()), message);
        }
    }
}

TEST(JobFile, DenoiseKey) {
    const JobFile f = parse_job_file(
        R"({"defaults": {"denoise": true},
            "jobs": [{"scene": "a.gltf"}, {"scene": "b.gltf", "denoise": false}]})",
        "/jobs/j.json");
    EXPECT_EQ(value(f.defaults, "denoise"), "1");
    EXPECT_FALSE(value(f.jobs[0].settings, "denoise"));
    EXPECT_EQ(value(f.jobs[1].settings, "denoise"), "0");
    try {
        parse_job_file(R"({"jobs": [{"scene": "a.gltf", "denoise": 1}]})", "j.json");
        FAIL() << "a number was taken for a flag";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()), "j.json: jobs[0].denoise: expected true or false");
    }
}

TEST(JobFile, StrictAndTextureLimitKeys) {
    const JobFile f = parse_job_file(
        R"({"defaults": {"strict": true, "max_texture_pixels": 4096},
            "jobs": [{"scene": "a.gltf", "strict": false}]})",
        "/jobs/j.json");
    EXPECT_EQ(value(f.defaults, "strict"), "1");
    EXPECT_EQ(number(f.defaults, "max_texture_pixels"), 4096);
    EXPECT_EQ(value(f.jobs[0].settings, "strict"), "0");
    EXPECT_FALSE(value(f.jobs[0].settings, "max_texture_pixels"));
    const std::pair<const char*, const char*> bad[] = {
        {R"("strict": "yes")", "j.json: jobs[0].strict: expected true or false"},
        {R"("max_texture_pixels": 0)",
         "j.json: jobs[0].max_texture_pixels: 0 is not in [1, 1099511627776]"},
        {R"("max_texture_pixels": -5)",
         "j.json: jobs[0].max_texture_pixels: '-5' is negative"},
        {R"("max_texture_pixels": 1.5)",
         "j.json: jobs[0].max_texture_pixels: expected an integer"}};
    for (const auto& [member, message] : bad) {
        try {
            parse_job_file(std::string(R"({"jobs": [{"scene": "a.gltf", )") + member + "}]}",
                           "j.json");
            FAIL() << member;
        } catch (const SceneError& e) {
            EXPECT_EQ(std::string(e.what()), message);
        }
    }
}

TEST(JobFile, FrameLists) {
    EXPECT_EQ(parse_frame_list("7"), std::vector<int>({7}));
    EXPECT_EQ(parse_frame_list("1-4"), std::vector<int>({1, 2, 3, 4}));
    EXPECT_EQ(parse_frame_list("1-8:3"), std::vector<int>({1, 4, 7}));
    EXPECT_EQ(parse_frame_list("0,5,10-11"), std::vector<int>({0, 5, 10, 11}));
    EXPECT_EQ(parse_frame_list("1-48").size(), 48u);
    for (const char* bad : {"", "a", "3-", "-3", "5-1", "1-4:0", "1,,2", "1-1000000"})
        EXPECT_THROW(parse_frame_list(bad), std::invalid_argument) << bad;
}

}  // namespace
}  // namespace penumbra
