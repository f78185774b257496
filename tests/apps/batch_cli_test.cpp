// End-to-end tests of batch rendering: a bad scene does not stop the batch, finished
// outputs are skipped (resume) unless --overwrite, output name templates, job files,
// frame ranges, and interrupted renders (Ctrl-C: a partial image; kill -9: nothing
// corrupt at the destination).
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>
#include <signal.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <regex>
#include <thread>

#include "support/cli_process.h"
#include "support/gltf_builder.h"
#include "support/paths.h"

namespace penumbra {
namespace {

namespace fs = std::filesystem;
using test::run_penumbra;

const std::string kCornell = test::source_path("scenes/cornell-box.gltf");
const std::string kBox = test::shared_path("scenes/khronos/Box.gltf");
// Small and fast: every test image is tiny.
const std::vector<std::string> kFast = {"--width", "16", "--spp", "1", "--no-preview"};

std::vector<std::string> args(std::vector<std::string> a, const std::vector<std::string>& more) {
    a.insert(a.end(), more.begin(), more.end());
    return a;
}

std::string attribute(const std::string& exr, const std::string& name) {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(exr);
    if (!in) return "<cannot open " + exr + ">";
    return in->spec().get_string_attribute(name, "<none>");
}

bool has_temp_files(const fs::path& dir) {
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.path().filename().string().rfind(".tmp", 0) == 0) return true;
    return false;
}

// Waits until the child's render loop runs (its progress log says "started"), then a
// little longer, so that a signal lands in the middle of rendering.
void wait_until_rendering(test::CliProcess& p, int ms) {
    ASSERT_TRUE(p.wait_for_output(": started, ", 30)) << p.wait().output;
    std::this_thread::sleep_for(std::chrono::milliseconds(ms));
}

std::string read_text(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(f), {});
}

TEST(BatchCli, BrokenSceneIsReportedAndTheOthersRender) {
    const test::ScratchDir dir;
    const std::string broken = dir.write("broken.gltf", "{\"asset\": ");
    const test::CliResult r = run_penumbra(
        args({"render", kCornell, broken, kBox, "--out-dir", dir.file("out")}, kFast));
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_TRUE(fs::exists(dir.file("out/cornell-box.exr")));
    EXPECT_TRUE(fs::exists(dir.file("out/Box.exr")));
    EXPECT_FALSE(fs::exists(dir.file("out/broken.exr")));
    // The summary table has a row per scene and the error of the broken one.
    EXPECT_NE(r.output.find("3 images: 2 ok, 0 partial, 1 failed, 0 skipped"),
              std::string::npos) << r.output;
    EXPECT_TRUE(std::regex_search(r.output, std::regex("broken\\.gltf +- +failed .*broken\\.gltf:")))
        << r.output;
    EXPECT_TRUE(std::regex_search(r.output, std::regex("Box\\.gltf +- +ok +[0-9.]+s +1 ")))
        << r.output;
}

TEST(BatchCli, ResumeSkipsFinishedImagesAndOverwriteRendersThemAgain) {
    const test::ScratchDir dir;
    const auto render = args({"render", kCornell, kBox, "--out-dir", dir.file("out")}, kFast);
    ASSERT_EQ(run_penumbra(render).status, 0);
    const std::string cornell = dir.file("out/cornell-box.exr"), box = dir.file("out/Box.exr");
    // Date the finished file back: a rewrite, however fast, would give it a new time.
    const auto old_time = fs::last_write_time(cornell) - std::chrono::hours(1);
    fs::last_write_time(cornell, old_time);
    const std::string cornell_bytes = read_text(cornell);
    // A partial image (as Ctrl-C leaves) is not finished: resume renders it again.
    {
        std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(box);
        OIIO::ImageSpec spec(2, 2, 3, OIIO::TypeDesc::FLOAT);
        spec.attribute("penumbra:partial", "1");
        const float pixels[12] = {};
        ASSERT_TRUE(out->open(box, spec) && out->write_image(OIIO::TypeDesc::FLOAT, pixels));
        out->close();
    }

    test::CliResult r = run_penumbra(render);
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(fs::last_write_time(cornell), old_time) << "a finished image was rewritten";
    EXPECT_EQ(read_text(cornell), cornell_bytes);
    EXPECT_TRUE(std::regex_search(r.output, std::regex("cornell-box\\.gltf +- +skipped")))
        << r.output;
    EXPECT_EQ(attribute(box, "penumbra:partial"), "0") << "the partial image was not redone";
    EXPECT_EQ(attribute(box, "penumbra:spp"), "1");

    r = run_penumbra(args(render, {"--overwrite"}));
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(fs::last_write_time(cornell), old_time) << "--overwrite did not render again";
    EXPECT_NE(r.output.find("2 images: 2 ok"), std::string::npos) << r.output;
}

TEST(BatchCli, NameTemplatesAndFrames) {
    const test::ScratchDir dir;
    test::CliResult r = run_penumbra(args({"render", kCornell, kBox, "--out-dir",
                                           dir.file("a"), "--name", "{index}-{scene}_{camera}.exr"},
                                          kFast));
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(fs::exists(dir.file("a/0-cornell-box_front.exr")));
    EXPECT_TRUE(fs::exists(dir.file("a/1-Box_default.exr"))) << "a camera made for the scene";

    // Frames: one image per frame at time frame / fps (a static scene looks the same).
    r = run_penumbra(args({"render", kCornell, "--frames", "3-7:2", "--fps", "10", "--out-dir",
                           dir.file("f")},
                          kFast));
    EXPECT_EQ(r.status, 0) << r.output;
    for (const char* f : {"3", "5", "7"})
        EXPECT_TRUE(fs::exists(dir.file("f/cornell-box_000" + std::string(f) + ".exr"))) << f;
    EXPECT_FALSE(fs::exists(dir.file("f/cornell-box_0004.exr")));
    EXPECT_EQ(attribute(dir.file("f/cornell-box_0005.exr"), "penumbra:frame"), "5");
    EXPECT_EQ(attribute(dir.file("f/cornell-box_0005.exr"), "penumbra:time"), "0.500000");

    // Two images may not write one file; a bad placeholder fails before rendering.
    r = run_penumbra(args({"render", kCornell, kBox, "--out-dir", dir.file("c"), "--name",
                           "same.exr"},
                          kFast));
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find("another image of this batch already writes it"), std::string::npos)
        << r.output;
    r = run_penumbra(args({"render", kCornell, "--out-dir", dir.file("d"), "--name", "{oops}.exr"},
                          kFast));
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find("unknown placeholder {oops}"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir.file("d")));
}

TEST(BatchCli, JobFileEntriesOverrideItsDefaultsWhichOverrideTheCommandLine) {
    const test::ScratchDir dir;
    // Relative paths in a job file are relative to the job file.
    const std::string box = fs::relative(kBox, dir.file("")).string();
    const std::string job = dir.write("jobs.json", R"({
      "defaults": {"width": 20, "spp": 2, "out_dir": "renders", "name": "{scene}_{camera}.exr"},
      "jobs": [
        {"scene": ")" + kCornell + R"("},
        {"scene": ")" + box + R"(", "width": 12, "height": 6, "spp": 3, "seed": 5,
         "integrator": "direct", "output": "custom/box.exr"},
        {"scene": ")" + kCornell + R"(", "frames": "1-2", "name": "anim_{frame}.exr",
         "camera": "front", "time_limit": 30}
      ]})");
    const test::CliResult r =
        run_penumbra({"render", "--job", job, "--spp", "7", "--seed", "3", "--no-preview"});
    ASSERT_EQ(r.status, 0) << r.output;
    auto size = [](const std::string& p) {
        std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(p);
        return in ? std::to_string(in->spec().width) + "x" + std::to_string(in->spec().height)
                  : std::string("missing");
    };
    const std::string first = dir.file("renders/cornell-box_front.exr");
    EXPECT_EQ(size(first), "20x20");
    EXPECT_EQ(attribute(first, "penumbra:spp"), "2");   // defaults beat the command line
    EXPECT_EQ(attribute(first, "penumbra:seed"), "3");  // the command line fills the rest
    const std::string second = dir.file("custom/box.exr");
    EXPECT_EQ(size(second), "12x6");
    EXPECT_EQ(attribute(second, "penumbra:spp"), "3");
    EXPECT_EQ(attribute(second, "penumbra:seed"), "5");
    EXPECT_EQ(attribute(second, "penumbra:integrator"), "direct");
    for (const char* f : {"0001", "0002"}) {
        const std::string p = dir.file("renders/anim_" + std::string(f) + ".exr");
        EXPECT_EQ(size(p), "20x20");
        EXPECT_EQ(attribute(p, "penumbra:time_limit"), "30.000000");
    }

    // Errors name the file and the element.
    const std::string bad = dir.write("bad.json", R"({"jobs": [{"scene": "x.gltf", "spp": "many"}]})");
    const test::CliResult e = run_penumbra({"render", "--job", bad});
    EXPECT_EQ(e.status, 1);
    EXPECT_NE(e.output.find("bad.json: jobs[0].spp: expected an integer"), std::string::npos)
        << e.output;
}

TEST(BatchCli, JobFileSetsColourAndExrOutputPerEntry) {
    const test::ScratchDir dir;
    const std::string job = dir.write("jobs.json", R"({
      "defaults": {"width": 12, "spp": 1, "out_dir": "renders", "compression": "piz"},
      "jobs": [
        {"scene": ")" + kCornell + R"(", "name": "plain.exr"},
        {"scene": ")" + kCornell + R"(", "name": "aces.exr", "working_space": "ACEScg",
         "output_colorspace": "ACES2065-1", "aov": "albedo,depth", "half": true,
         "compression": "zip", "view": "ACES 1.0 - SDR Video"}
      ]})");
    const test::CliResult r = run_penumbra({"render", "--job", job, "--no-preview", "-q"});
    ASSERT_EQ(r.status, 0) << r.output;
    auto spec = [](const std::string& p) {
        std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(p);
        return in ? in->spec() : OIIO::ImageSpec();
    };
    const OIIO::ImageSpec plain = spec(dir.file("renders/plain.exr"));
    EXPECT_EQ(plain.get_string_attribute("compression"), "piz");
    EXPECT_EQ(plain.nchannels, 4);
    EXPECT_EQ(plain.get_string_attribute("penumbra:working_space"), "Linear Rec.709 (sRGB)");
    const OIIO::ImageSpec aces = spec(dir.file("renders/aces.exr"));
    EXPECT_EQ(aces.get_string_attribute("compression"), "zip");
    EXPECT_EQ(aces.get_string_attribute("penumbra:working_space"), "ACEScg");
    EXPECT_EQ(aces.get_string_attribute("penumbra:colorspace"), "ACES2065-1");
    EXPECT_GE(aces.channelindex("Albedo.R"), 0);
    EXPECT_GE(aces.channelindex("Depth.Z"), 0);
    ASSERT_GE(aces.channelindex("R"), 0);
    EXPECT_EQ(aces.channelformats.at(size_t(aces.channelindex("R"))), OIIO::TypeDesc::HALF);

    // A bad value is an error naming the entry and its key, before anything renders.
    const std::string bad = dir.write("bad.json", R"({"jobs": [{"scene": ")" + kCornell +
                                                      R"(", "aov": "albedo,colour"}]})");
    const test::CliResult e = run_penumbra({"render", "--job", bad, "--no-preview"});
    EXPECT_EQ(e.status, 1);
    EXPECT_NE(e.output.find("bad.json: jobs[0].aov: "), std::string::npos) << e.output;
    EXPECT_NE(e.output.find("colour"), std::string::npos) << e.output;
}

TEST(BatchCli, SummaryTableGivesEachImagesErrorAgainstTheReference) {
    const test::ScratchDir dir;
    const std::string ref = dir.file("ref.exr");
    ASSERT_EQ(run_penumbra(args({"render", kCornell, "-o", ref, "-q"}, kFast)).status, 0);
    const test::CliResult r = run_penumbra(args(
        {"render", kCornell, kCornell, "--out-dir", dir.file("out"), "--name", "{index}.exr",
         "--reference", ref, "--seed", "4"},
        kFast));
    ASSERT_EQ(r.status, 0) << r.output;
    // The header row names the column, and each image's row carries a number in it.
    EXPECT_NE(r.output.find("relMSE"), std::string::npos) << r.output;
    const std::regex row(R"(cornell-box\.gltf\s+\S+\s+ok\s+\S+\s+1\s+\S+\s+(\d\.\d{4}e[-+]\d+))");
    auto it = std::sregex_iterator(r.output.begin(), r.output.end(), row);
    int rows = 0;
    for (; it != std::sregex_iterator(); ++it) {
        ++rows;
        EXPECT_GT(std::stod((*it)[1].str()), 0.0);  // another seed than the reference's
    }
    EXPECT_EQ(rows, 2) << r.output;
}

TEST(BatchCli, TimeLimitStopsBetweenPassesAndRecordsTheSamplesDone) {
    const test::ScratchDir dir;
    const test::CliResult r =
        run_penumbra({"render", kCornell, "-o", dir.file("t.exr"), "--width", "32", "--spp",
                      "1000000", "--time-limit", "0.3", "--no-preview", "-q"});
    ASSERT_EQ(r.status, 0) << r.output;
    const int spp = std::stoi(attribute(dir.file("t.exr"), "penumbra:spp"));
    EXPECT_GE(spp, 1);
    EXPECT_LT(spp, 1000000);
    EXPECT_EQ(attribute(dir.file("t.exr"), "penumbra:spp_requested"), "1000000");
    EXPECT_EQ(attribute(dir.file("t.exr"), "penumbra:partial"), "0");
}

TEST(BatchCli, CtrlCWritesAPartialImageAndNoTempFiles) {
    const test::ScratchDir dir;
    const std::string out = dir.file("out/cb.exr");
    test::CliProcess p({"render", kCornell, "-o", out, "--width", "32", "--spp", "1000000"});
    wait_until_rendering(p, 200);
    p.signal(SIGINT);
    const test::CliResult r = p.wait();
    EXPECT_EQ(r.status, 130) << r.output;
    EXPECT_EQ(attribute(out, "penumbra:partial"), "1") << r.output;
    const int spp = std::stoi(attribute(out, "penumbra:spp"));
    EXPECT_GE(spp, 1);
    EXPECT_LT(spp, 1000000);
    EXPECT_TRUE(fs::exists(dir.file("out/cb.png")));
    EXPECT_FALSE(has_temp_files(dir.file("")));
}

TEST(BatchCli, SecondCtrlCAbandonsTheImageWithoutTempFiles) {
    const test::ScratchDir dir;
    const std::string out = dir.file("cb.exr");
    test::CliProcess p({"render", kCornell, kBox, "-o", dir.file("{scene}.exr"), "--width",
                        "32", "--spp", "1000000"});
    // Late enough that passes last a while, so both signals land within one.
    wait_until_rendering(p, 600);
    p.signal(SIGINT);
    std::this_thread::sleep_for(std::chrono::milliseconds(30));
    p.signal(SIGINT);
    const test::CliResult r = p.wait();
    EXPECT_EQ(r.status, 130) << r.output;
    EXPECT_FALSE(has_temp_files(dir.file("")));
    // Normally nothing is written; should the pass have ended between the two signals,
    // the file is a complete partial image.
    if (fs::exists(out)) {
        EXPECT_EQ(attribute(out, "penumbra:partial"), "1");
    }
    // The batch stops: the second scene does not start.
    EXPECT_FALSE(fs::exists(dir.file("Box.exr")));
    EXPECT_TRUE(std::regex_search(r.output, std::regex("Box\\.gltf +- +skipped")))
        << r.output;
}

TEST(BatchCli, KillLeavesTheOldOutputOrNothing) {
    const test::ScratchDir dir;
    const std::string out = dir.file("cb.exr");
    for (bool had_old_file : {false, true}) {
        if (had_old_file) std::ofstream(out) << "previous render";
        test::CliProcess p({"render", kCornell, "-o", out, "--width", "32", "--spp", "1000000",
                            "--overwrite"});
        wait_until_rendering(p, 200);
        p.signal(SIGKILL);
        EXPECT_EQ(p.wait().status, 128 + SIGKILL);
        if (had_old_file)
            EXPECT_EQ(read_text(out), "previous render");
        else
            EXPECT_FALSE(fs::exists(out));
    }
}

}  // namespace
}  // namespace penumbra
