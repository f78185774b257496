// End-to-end tests of checkpoints and the farm's steps without a cluster: SIGTERM stops
// a render with a checkpoint and the same command finishes it bit for bit as an
// uninterrupted render; kill -9 loses only the work since the last timed checkpoint; a
// stale checkpoint is not resumed; and `farm task` for every work item plus `farm merge`
// writes images (banded or not, AOVs, half, denoised) with the pixels and header of
// `render --job`, the tasks run under every Embree ISA the CPU has.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <signal.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <thread>

#include "support/cli_process.h"
#include "support/embree_isas.h"
#include "support/exr_pixels.h"
#include "support/gltf_builder.h"
#include "support/paths.h"

namespace penumbra {
namespace {

namespace fs = std::filesystem;
using test::run_penumbra;

const std::string kCornell = test::source_path("scenes/cornell-box.gltf");
const std::string kBox = test::shared_path("scenes/khronos/Box.gltf");

using test::same_pixels;

std::string attribute(const std::string& exr, const std::string& name) {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(exr);
    if (!in) return "<cannot open " + exr + ">";
    return in->spec().get_string_attribute(name, "<none>");
}

// Header attributes as text, but those of OIIO's reader ("oiio:", "openexr:").
std::map<std::string, std::string> header(const std::string& exr) {
    std::map<std::string, std::string> out;
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(exr);
    if (!in) return out;
    for (const OIIO::ParamValue& p : in->spec().extra_attribs) {
        const std::string name = p.name().string();
        if (name.rfind("oiio:", 0) == 0) continue;
        out[name] = in->spec().metadata_val(p);
    }
    return out;
}

// A render of the Cornell box that takes a second or two here (a quarter second on an
// idle 2-core machine): a SIGTERM as soon as it starts lands well before its last pass,
// which holds half the samples.
std::vector<std::string> cornell_render(const std::string& out, const std::string& spp) {
    return {"render",      kCornell, "-o", out,     "--width",
            "32",          "--spp",  spp,  "--aov", "albedo,depth,variance,samples",
            "--no-preview"};
}

TEST(FarmCli, SigtermCheckpointsAndTheSameCommandFinishesBitwise) {
    const test::ScratchDir dir;
    const std::string ref = dir.file("ref.exr"), out = dir.file("out.exr");
    ASSERT_EQ(run_penumbra(cornell_render(ref, "256")).status, 0);
    {
        test::CliProcess p(cornell_render(out, "256"));
        ASSERT_TRUE(p.wait_for_output(": started, ", 30)) << p.wait().output;
        p.signal(SIGTERM);
        const test::CliResult r = p.wait();
        EXPECT_EQ(r.status, 143) << r.output;  // 128 + SIGTERM, as a shell reports it
        ASSERT_EQ(attribute(out, "penumbra:partial"), "1") << r.output;
        ASSERT_TRUE(fs::exists(out + ".ckpt")) << r.output;
        EXPECT_LT(std::stoi(attribute(out, "penumbra:spp")), 256);
    }
    const test::CliResult r = run_penumbra(cornell_render(out, "256"));
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("resuming from the checkpoint at "), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out + ".ckpt")) << "the checkpoint outlived its finished image";
    EXPECT_TRUE(same_pixels(ref, out));
    // The header too, rays traced included: the resumed image is the same render.
    EXPECT_EQ(header(ref), header(out));
}

TEST(FarmCli, KillNineLosesOnlyTheWorkSinceTheLastTimedCheckpoint) {
    const test::ScratchDir dir;
    const std::string ref = dir.file("ref.exr"), out = dir.file("out.exr");
    ASSERT_EQ(run_penumbra(cornell_render(ref, "256")).status, 0);
    {
        // A checkpoint at every pass boundary.
        std::vector<std::string> args = cornell_render(out, "256");
        args.insert(args.end(), {"--checkpoint-interval", "0.001"});
        test::CliProcess p(args);
        ASSERT_TRUE(p.wait_for_output(": started, ", 30)) << p.wait().output;
        for (int i = 0; i < 200 && !fs::exists(out + ".ckpt"); ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        p.signal(SIGKILL);
        ASSERT_EQ(p.wait().status, 128 + SIGKILL);
    }
    ASSERT_TRUE(fs::exists(out + ".ckpt"));
    EXPECT_FALSE(fs::exists(out));  // no half-written image either
    const test::CliResult r = run_penumbra(cornell_render(out, "256"));
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("resuming from the checkpoint at "), std::string::npos) << r.output;
    EXPECT_TRUE(same_pixels(ref, out));
}

TEST(FarmCli, ACheckpointOfOtherOptionsIsNotResumed) {
    const test::ScratchDir dir;
    const std::string out = dir.file("out.exr");
    {
        test::CliProcess p(cornell_render(out, "256"));
        ASSERT_TRUE(p.wait_for_output(": started, ", 30)) << p.wait().output;
        p.signal(SIGTERM);
        ASSERT_EQ(p.wait().status, 143);
    }
    ASSERT_TRUE(fs::exists(out + ".ckpt"));
    // Another sample count lays out other strata: the checkpoint is stale.
    const test::CliResult r = run_penumbra(cornell_render(out, "8"));
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("the checkpoint is of another scene or other options; rendering "
                            "from sample 0"),
              std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("resuming"), std::string::npos) << r.output;
    EXPECT_TRUE(same_pixels(
        out, (run_penumbra(cornell_render(dir.file("ref.exr"), "8")), dir.file("ref.exr"))));
}

// A job file: a banded image with AOVs, a banded half-float image, a broken scene, an
// unbanded image and an animation's frames; out_dir differs between the two copies.
std::string job_file(const test::ScratchDir& dir, const std::string& name,
                     const std::string& out_dir) {
    dir.write("broken.gltf", "{\"asset\": ");
    return dir.write(name, R"({
  "defaults": {"width": 24, "spp": 3, "out_dir": ")" +
                               out_dir + R"("},
  "jobs": [
    {"scene": ")" + kCornell + R"(", "bands": 3, "name": "banded.exr",
     "aov": "albedo,normal,depth,position,variance,samples"},
    {"scene": ")" + kBox + R"(", "bands": 5, "half": true, "name": "box_half.exr"},
    {"scene": "broken.gltf"},
    {"scene": ")" + kCornell + R"(", "name": "frame_{frame}.exr", "frames": "1-3",
     "frames_per_task": 2}
  ]
})");
}

TEST(FarmCli, TasksAndMergeWriteTheImagesOfRenderJob) {
    const test::ScratchDir dir;
    const std::string ref_job = job_file(dir, "ref.json", "ref");
    const std::string farm_job = job_file(dir, "farm.json", "farm");
    const test::CliResult ref = run_penumbra({"render", "--job", ref_job, "-q"});
    EXPECT_EQ(ref.status, 1) << ref.output;  // the broken scene
    // 3 + 5 bands, the broken scene, 3 frames in 2 tasks: 11 work items, run here one by
    // one, each under another of the Embree ISAs this CPU has (as on a cluster of mixed
    // nodes), while the reference ran under Embree's own choice.
    const std::vector<std::string> isas = test::embree_isas();
    for (int i = 0; i < 11; ++i) {
        const test::ScopedEmbreeIsa isa(isas.empty() ? "" : isas[i % isas.size()]);
        const test::CliResult t =
            run_penumbra({"farm", "task", farm_job, "--index", std::to_string(i)});
        EXPECT_EQ(t.status, i == 8 ? 1 : 0) << i << ": " << t.output;
    }
    EXPECT_TRUE(fs::exists(dir.file("farm/banded.band-2-of-3.exr")));
    const test::CliResult m = run_penumbra({"farm", "merge", farm_job});
    EXPECT_EQ(m.status, 1) << m.output;
    EXPECT_TRUE(std::regex_search(m.output, std::regex("broken\\.gltf +- +failed .*broken\\.gltf")))
        << m.output;
    EXPECT_NE(m.output.find("6 images: 5 ok, 0 partial, 1 failed"), std::string::npos) << m.output;
    for (const char* name : {"banded.exr", "banded.png", "box_half.exr", "box_half.png",
                             "frame_0001.exr", "frame_0002.exr", "frame_0003.exr"}) {
        EXPECT_TRUE(same_pixels(dir.file(std::string("ref/") + name),
                                dir.file(std::string("farm/") + name)))
            << name;
    }
    for (const char* name : {"banded.exr", "box_half.exr", "frame_0002.exr"})
        EXPECT_EQ(header(dir.file(std::string("ref/") + name)),
                  header(dir.file(std::string("farm/") + name)))
            << name;
    // The band files are gone once merged.
    EXPECT_FALSE(fs::exists(dir.file("farm/banded.band-2-of-3.exr")));
    EXPECT_FALSE(fs::exists(dir.file("farm/banded.band-2-of-3.png")));
    EXPECT_TRUE(fs::exists(dir.file("farm.farm/summary.txt")));
}

// Denoised images: one in float with AOVs, an exposure and an output space other than the
// working space (so the denoised RGB goes through the writer's whole conversion), one in
// half; out_dir differs between the two copies.
std::string denoise_job_file(const test::ScratchDir& dir, const std::string& name,
                             const std::string& out_dir) {
    return dir.write(name, R"({
  "defaults": {"width": 24, "spp": 4, "denoise": true, "out_dir": ")" +
                               out_dir + R"("},
  "jobs": [
    {"scene": ")" + kCornell + R"(", "bands": 3, "name": "denoised.exr",
     "aov": "albedo,depth,variance", "exposure": 0.5, "working_space": "ACEScg",
     "output_colorspace": "ACES2065-1"},
    {"scene": ")" + kCornell + R"(", "bands": 2, "half": true, "name": "denoised_half.exr"}
  ]
})");
}

TEST(FarmCli, MergeDenoisesTheAssembledBandsToTheBitsOfOneMachine) {
    const test::ScratchDir dir;
    const std::string ref_job = denoise_job_file(dir, "ref.json", "ref");
    const std::string farm_job = denoise_job_file(dir, "farm.json", "farm");
    const test::CliResult ref = run_penumbra({"render", "--job", ref_job, "-q"});
    ASSERT_EQ(ref.status, 0) << ref.output;
    // 3 + 2 bands, each under another of this CPU's Embree ISAs.
    const std::vector<std::string> isas = test::embree_isas();
    for (int i = 0; i < 5; ++i) {
        const test::ScopedEmbreeIsa isa(isas.empty() ? "" : isas[i % isas.size()]);
        const test::CliResult t =
            run_penumbra({"farm", "task", farm_job, "--index", std::to_string(i)});
        EXPECT_EQ(t.status, 0) << i << ": " << t.output;
    }
    // A band carries the denoiser's input, full float under half; it is not denoised.
    {
        const std::string band = dir.file("farm/denoised_half.band-1-of-2.exr");
        std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(band);
        ASSERT_TRUE(in) << band;
        const int visibility = in->spec().channelindex("DenoiseInput.GuideB.Visibility");
        ASSERT_GE(visibility, 0);
        EXPECT_EQ(in->spec().channelformat(visibility), OIIO::TypeDesc::FLOAT);
        EXPECT_EQ(in->spec().channelformat(in->spec().channelindex("R")), OIIO::TypeDesc::HALF);
        EXPECT_EQ(in->spec().get_string_attribute("penumbra:denoise", "<none>"), "<none>");
    }
    const test::CliResult m = run_penumbra({"farm", "merge", farm_job});
    EXPECT_EQ(m.status, 0) << m.output;
    EXPECT_NE(m.output.find("estimate"), std::string::npos) << m.output;
    for (const char* name :
         {"denoised.exr", "denoised.png", "denoised_half.exr", "denoised_half.png"}) {
        EXPECT_TRUE(same_pixels(dir.file(std::string("ref/") + name),
                                dir.file(std::string("farm/") + name)))
            << name;
    }
    for (const char* name : {"denoised.exr", "denoised_half.exr"}) {
        const std::string farm = dir.file(std::string("farm/") + name);
        EXPECT_EQ(header(dir.file(std::string("ref/") + name)), header(farm)) << name;
        EXPECT_NE(attribute(farm, "penumbra:denoise"), "<none>") << name;
        EXPECT_NE(attribute(farm, "penumbra:denoise_relmse_estimate"), "<none>") << name;
        const test::Pixels p = test::read_pixels(farm);
        EXPECT_NE(std::find(p.channels.begin(), p.channels.end(), "Noisy.R"), p.channels.end());
        for (const std::string& c : p.channels)
            EXPECT_EQ(c.rfind("DenoiseInput.", 0), std::string::npos) << c;
    }
    EXPECT_FALSE(fs::exists(dir.file("farm/denoised.band-3-of-3.exr")));
}

// A nearly black image (the Cornell box at -12 EV: its brightest pixels, the light's
// radiance 30, come to 0.007, under the 0.01 a lit pixel needs) warns once merged,
// as one machine's render does: the same penumbra:image_warning (an exposure of whole
// stops scales every pixel exactly, so the two measure the same numbers), and the farm's
// table flags it. Its bands, parts of the image, do not warn.
TEST(FarmCli, MergeWarnsOfANearlyBlackImageAsOneMachineDoes) {
    const test::ScratchDir dir;
    const auto job = [&](const std::string& name, const std::string& out_dir) {
        return dir.write(name, R"({"defaults": {"width": 24, "spp": 2, "out_dir": ")" + out_dir +
                                   R"(", "exposure": -12, "default_light": "off"},
  "jobs": [{"scene": ")" + kCornell + R"(", "bands": 2, "name": "dark.exr"}]})");
    };
    const std::string ref_job = job("ref.json", "ref"), farm_job = job("farm.json", "farm");
    const test::CliResult ref = run_penumbra({"render", "--job", ref_job});
    ASSERT_EQ(ref.status, 0) << ref.output;
    const std::string warning = attribute(dir.file("ref/dark.exr"), "penumbra:image_warning");
    ASSERT_EQ(warning.rfind("image nearly black: ", 0), 0u) << warning;
    for (int i = 0; i < 2; ++i) {
        const test::CliResult t =
            run_penumbra({"farm", "task", farm_job, "--index", std::to_string(i)});
        ASSERT_EQ(t.status, 0) << t.output;
        EXPECT_EQ(t.output.find("image nearly black"), std::string::npos) << t.output;
    }
    const test::CliResult m = run_penumbra({"farm", "merge", farm_job});
    ASSERT_EQ(m.status, 0) << m.output;
    EXPECT_NE(m.output.find("image nearly black"), std::string::npos) << m.output;
    EXPECT_TRUE(std::regex_search(m.output, std::regex("cornell-box\\.gltf .* BLACK .*dark\\.exr")))
        << m.output;
    EXPECT_EQ(attribute(dir.file("farm/dark.exr"), "penumbra:image_warning"), warning);
    EXPECT_EQ(header(dir.file("ref/dark.exr")), header(dir.file("farm/dark.exr")));
}

TEST(FarmCli, ATaskRefusesAJobFileChangedSinceSubmit) {
    const test::ScratchDir dir;
    const std::string job = dir.write(
        "job.json", R"({"jobs": [{"scene": ")" + kCornell + R"(", "width": 8, "spp": 1}]})");
    fs::create_directories(dir.file("job.farm"));
    dir.write("job.farm/plan.txt", "0 job 0 band - frame - another.gltf\n");
    const test::CliResult t = run_penumbra({"farm", "task", job, "--index", "0"});
    EXPECT_EQ(t.status, 1) << t.output;
    EXPECT_NE(t.output.find("changed since it was submitted"), std::string::npos) << t.output;
    EXPECT_FALSE(fs::exists(dir.file("out/cornell-box.exr")));
    const test::CliResult m = run_penumbra({"farm", "merge", job});
    EXPECT_EQ(m.status, 1) << m.output;
    EXPECT_TRUE(std::regex_search(
        m.output, std::regex("cornell-box\\.gltf +- +failed .*changed since it was submitted")))
        << m.output;
}

}  // namespace
}  // namespace penumbra
