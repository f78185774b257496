#include "job/option_table.h"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "job/job_file.h"

namespace penumbra {
namespace {

// A valid value of d other than the one o holds, as text; empty when none was found.
std::string other_value(const OptionDecl& d, const RenderCommandOptions& o) {
    std::vector<std::string> candidates;
    switch (d.kind) {
        case OptionKind::Flag: candidates = {d.get(o) == "1" ? "0" : "1"}; break;
        case OptionKind::Choice: candidates = d.choices; break;
        case OptionKind::Integer:
        case OptionKind::Number: candidates = {"2", "3", "0.5", "1", "7", "0", "-1"}; break;
        case OptionKind::Numbers: candidates = {d.count == 2 ? "1 2" : "1 2 3"}; break;
        case OptionKind::Text:
        case OptionKind::Path: candidates = {"1-3", "albedo", "probe"}; break;
    }
    for (const std::string& c : candidates) {
        RenderCommandOptions p = o;
        try {
            d.set(p, c);
        } catch (const std::invalid_argument&) {
            continue;
        }
        if (d.get(p) != d.get(o)) return c;
    }
    return "";
}

// The fingerprint of a checkpoint is every pixel-deciding option's text: changing any of
// them must change it, and changing any other option must not.
TEST(OptionTable, PixelDecidingOptionsChangeTheFingerprintAndNoOthersDo) {
    const RenderCommandOptions defaults;
    const std::string before = pixel_options_text(defaults);
    for (const OptionDecl& d : render_option_table()) {
        const std::string value = other_value(d, defaults);
        ASSERT_FALSE(value.empty()) << "--" << d.flag << ": no other valid value found";
        RenderCommandOptions o = defaults;
        d.set(o, value);
        if (d.pixels)
            EXPECT_NE(pixel_options_text(o), before) << "--" << d.flag << " " << value;
        else
            EXPECT_EQ(pixel_options_text(o), before) << "--" << d.flag << " " << value;
    }
}

// Each option reads back what it writes, so job files, headers and fingerprints agree
// with the command line, and setting one option leaves every other as it was.
TEST(OptionTable, EachOptionRoundTripsAndTouchesOnlyItself) {
    const RenderCommandOptions defaults;
    for (const OptionDecl& d : render_option_table()) {
        const std::string value = other_value(d, defaults);
        RenderCommandOptions o = defaults;
        d.set(o, value);
        const std::string text = d.get(o);
        RenderCommandOptions again = defaults;
        d.set(again, text);
        EXPECT_EQ(d.get(again), text) << "--" << d.flag;
        for (const OptionDecl& other : render_option_table()) {
            // --no-default-light is a spelling of --default-light off.
            if (&other == &d || other.flag == "no-default-light" ||
                (d.flag == "no-default-light" && other.flag == "default-light"))
                continue;
            EXPECT_EQ(other.get(o), other.get(defaults)) << "--" << d.flag << " changed --"
                                                         << other.flag;
        }
    }
}

TEST(OptionTable, NamesAndKeysAreUnique) {
    std::set<std::string> flags, keys, headers;
    for (const OptionDecl& d : render_option_table()) {
        EXPECT_TRUE(flags.insert(d.flag).second) << d.flag;
        if (!d.job_key.empty()) EXPECT_TRUE(keys.insert(d.job_key).second) << d.job_key;
        if (!d.header_key.empty()) EXPECT_TRUE(headers.insert(d.header_key).second) << d.header_key;
        EXPECT_FALSE(d.help.empty()) << d.flag;
        EXPECT_EQ(find_option(d.flag), &d);
        if (!d.job_key.empty()) EXPECT_EQ(find_option(d.job_key), &d);
    }
}

TEST(OptionTable, ChoicesAreTypedValuesAndUnknownNamesAreNamed) {
    RenderCommandOptions o;
    set_render_option(o, "integrator", "direct");
    EXPECT_EQ(o.integrator, IntegratorType::Direct);
    set_render_option(o, "light-sampler", "bvh");
    EXPECT_EQ(o.lights.sampler, LightSamplerType::Bvh);
    set_render_option(o, "accel", "bvh");  // the SAH BVH's short name
    EXPECT_EQ(o.accel, AccelType::BvhSah);
    EXPECT_EQ(render_option("accel").get(o), "bvh-sah");
    set_render_option(o, "filter", "blackman-harris");
    EXPECT_EQ(o.filter, FilterType::BlackmanHarris);
    try {
        set_render_option(o, "filter", "mitchell");
        FAIL() << "an unknown filter was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("'mitchell'"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("box, gaussian, blackman-harris"), std::string::npos)
            << e.what();
    }
    EXPECT_THROW(set_render_option(o, "spp", "0"), std::invalid_argument);
    EXPECT_THROW(set_render_option(o, "spp", "12x"), std::invalid_argument);
    EXPECT_THROW(set_render_option(o, "clamp-indirect", "-1"), std::invalid_argument);
    EXPECT_THROW(set_render_option(o, "env-color", "1 2"), std::invalid_argument);
    EXPECT_EQ(sampler_name(SamplerType::TabledSobol), "tabled-sobol");
}

// A job file takes every option that has a job key, with the command line's checks.
TEST(OptionTable, JobFilesTakeEveryKeyedOption) {
    const RenderCommandOptions defaults;
    for (const OptionDecl& d : render_option_table()) {
        if (d.job_key.empty()) continue;
        const std::string value = other_value(d, defaults);
        std::string json;
        switch (d.kind) {
            case OptionKind::Flag: json = value == "1" ? "true" : "false"; break;
            case OptionKind::Integer:
            case OptionKind::Number: json = value; break;
            case OptionKind::Numbers: json = "[" + std::string(d.count == 2 ? "1, 2" : "1, 2, 3") + "]"; break;
            default: json = "\"" + value + "\""; break;
        }
        const std::string text = "{\"jobs\": [{\"scene\": \"a.gltf\", \"" + d.job_key + "\": " +
                                 json + "}]}";
        const JobFile file = parse_job_file(text, "/jobs/job.json");
        ASSERT_EQ(file.jobs.size(), 1u);
        ASSERT_EQ(file.jobs[0].settings.size(), 1u) << d.job_key;
        EXPECT_EQ(file.jobs[0].settings[0].option, &d);
    }
    EXPECT_THROW(parse_job_file("{\"jobs\": [{\"scene\": \"a.gltf\", \"spp\": \"16\"}]}", "j.json"),
                 std::exception);
    EXPECT_THROW(parse_job_file("{\"jobs\": [{\"scene\": \"a.gltf\", \"sppp\": 16}]}", "j.json"),
                 std::exception);
}

// The header echoes the options that have header keys, as before the table existed.
TEST(OptionTable, HeaderEchoesDeclaredOptions) {
    RenderCommandOptions o;
    set_render_option(o, "clamp-indirect", "0.5");
    set_render_option(o, "accel", "grid");
    const Metadata m = option_metadata(o);
    auto find = [&](const std::string& key) -> const MetadataValue* {
        for (const auto& [k, v] : m)
            if (k == key) return &v;
        return nullptr;
    };
    ASSERT_NE(find("penumbra:clamp_indirect"), nullptr);
    EXPECT_EQ(std::get<std::string>(*find("penumbra:clamp_indirect")), "0.500000");
    EXPECT_EQ(find("penumbra:clamp_direct"), nullptr);  // off: not written
    EXPECT_EQ(std::get<std::string>(*find("penumbra:accelerator")), "grid");
    EXPECT_EQ(std::get<std::string>(*find("penumbra:spp_requested")), "16");
    EXPECT_EQ(std::get<float>(*find("penumbra:exposure")), 0.0f);
    EXPECT_EQ(find("penumbra:adaptive_min_spp"), nullptr);
    set_render_option(o, "target-error", "0.02");
    EXPECT_NE(option_metadata(o).size(), m.size());
}

}  // namespace
}  // namespace penumbra
