// The timeline options end to end: the shutter interval in the EXR header for each form,
// conflicts reported as errors before anything renders, --frames giving each frame its
// own shutter, and check-accel taking the same options.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <filesystem>

#include "support/cli_process.h"
#include "support/gltf_builder.h"
#include "support/paths.h"

namespace penumbra {
namespace {

namespace fs = std::filesystem;
using test::run_penumbra;

const std::string kBoxAnimated = test::shared_path("scenes/khronos/BoxAnimated.gltf");

std::string attribute(const std::string& exr, const std::string& name) {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(exr);
    if (!in) return "<cannot open " + exr + ">";
    return in->spec().get_string_attribute(name, "<none>");
}

std::vector<std::string> render(const std::string& out, std::vector<std::string> more) {
    std::vector<std::string> a = {"render", kBoxAnimated, "-o", out, "--width", "16",
                                  "--spp", "1", "--no-preview", "-q"};
    a.insert(a.end(), more.begin(), more.end());
    return a;
}

TEST(TimelineCli, ShutterIntervalIsInTheHeader) {
    const test::ScratchDir dir;
    struct Case {
        std::vector<std::string> options;
        const char* open;
        const char* close;
    } cases[] = {
        {{}, "0.000000", "0.000000"},
        {{"--time", "1.875"}, "1.875000", "1.875000"},
        {{"--shutter-open", "0.5", "--shutter-close", "0.75"}, "0.500000", "0.750000"},
        {{"--frame", "12", "--fps", "24", "--shutter", "0.5"}, "0.500000", "0.520833"},
    };
    for (size_t i = 0; i < std::size(cases); ++i) {
        const std::string out = dir.file("t" + std::to_string(i) + ".exr");
        const auto r = run_penumbra(render(out, cases[i].options));
        ASSERT_EQ(r.status, 0) << r.output;
        EXPECT_EQ(attribute(out, "penumbra:shutter_open"), cases[i].open) << i;
        EXPECT_EQ(attribute(out, "penumbra:shutter_close"), cases[i].close) << i;
    }
}

TEST(TimelineCli, ConflictsFailBeforeRendering) {
    const test::ScratchDir dir;
    const std::string out = dir.file("x.exr");
    struct Case {
        std::vector<std::string> options;
        const char* message;
    } cases[] = {
        {{"--time", "1", "--shutter-open", "0", "--shutter-close", "1"},
         "--time (an instant) conflicts with --shutter-open"},
        {{"--shutter-open", "1"}, "--shutter-open and --shutter-close must be given together"},
        {{"--shutter-open", "2", "--shutter-close", "1"}, "is before --shutter-open"},
        {{"--shutter", "0.5"}, "needs --frame or --frames"},
        {{"--frame", "2", "--frames", "1-3"}, "--frame conflicts with --frames"},
        {{"--frame", "2", "--time", "1"}, "--frame conflicts with --time"},
    };
    for (const Case& c : cases) {
        const auto r = run_penumbra(render(out, c.options));
        EXPECT_NE(r.status, 0) << c.message;
        EXPECT_NE(r.output.find(c.message), std::string::npos) << r.output;
        EXPECT_FALSE(fs::exists(out)) << c.message;
    }
}

TEST(TimelineCli, FramesEachGetTheirShutter) {
    const test::ScratchDir dir;
    const auto r = run_penumbra({"render", kBoxAnimated, "--frames", "2-3", "--fps", "4",
                                 "--shutter", "0.5", "--out-dir", dir.file("f"), "--width",
                                 "16", "--spp", "1", "--no-preview", "-q"});
    ASSERT_EQ(r.status, 0) << r.output;
    const std::string f3 = dir.file("f/BoxAnimated_0003.exr");
    EXPECT_EQ(attribute(f3, "penumbra:frame"), "3");
    EXPECT_EQ(attribute(f3, "penumbra:shutter_open"), "0.750000");
    EXPECT_EQ(attribute(f3, "penumbra:shutter_close"), "0.875000");
    EXPECT_EQ(attribute(dir.file("f/BoxAnimated_0002.exr"), "penumbra:shutter_open"),
              "0.500000");
}

TEST(TimelineCli, CheckAccelTakesTheSameOptions) {
    auto r = run_penumbra({"check-accel", kBoxAnimated, "--rays", "200", "--width", "8",
                           "--time", "1", "--shutter-open", "0", "--shutter-close", "1"});
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("--time (an instant) conflicts"), std::string::npos) << r.output;
    r = run_penumbra({"check-accel", kBoxAnimated, "--rays", "200", "--width", "8",
                      "--time", "1.875"});
    EXPECT_EQ(r.status, 0) << r.output;
}

}  // namespace
}  // namespace penumbra
