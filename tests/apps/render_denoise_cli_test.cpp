// `render --denoise` end to end: the EXR's RGB is the denoised image and the layer
// Noisy.R/G/B the film's own estimate, bit for bit that of a render with the error AOV's
// sample split; the header names the method and its estimate; the job-file key, frames,
// AOVs and --reference work with it; fewer than 2 samples per pixel are refused (or, when
// a time limit stops the render there, left undenoised); and the file is the same for any
// thread count.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>

#include "core/denoise/nfor_denoiser.h"
#include "support/cli_process.h"
#include "support/exr_pixels.h"
#include "support/gltf_builder.h"
#include "support/paths.h"

namespace penumbra {
namespace {

using Args = std::vector<std::string>;
const std::string kCornell = test::source_path("scenes/cornell-box.gltf");

// penumbra render on the Cornell box, small, plus `more`.
test::CliResult render(const Args& more) {
    Args args = {"render", kCornell, "--spp", "4", "--width", "32", "--seed", "3"};
    args.insert(args.end(), more.begin(), more.end());
    return test::run_penumbra(args);
}

OIIO::ImageSpec header(const std::string& path) {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    EXPECT_TRUE(in) << OIIO::geterror();
    return in ? in->spec() : OIIO::ImageSpec();
}

// The named channels of every pixel of an EXR, in that order.
std::vector<float> channels(const test::Pixels& p, const std::vector<std::string>& names) {
    std::vector<size_t> index;
    for (const std::string& n : names) {
        const auto it = std::find(p.channels.begin(), p.channels.end(), n);
        EXPECT_NE(it, p.channels.end()) << n;
        if (it == p.channels.end()) return {};
        index.push_back(size_t(it - p.channels.begin()));
    }
    std::vector<float> out;
    for (size_t px = 0; px < size_t(p.width) * p.height; ++px)
        for (size_t i : index) out.push_back(p.data[px * p.channels.size() + i]);
    return out;
}

bool same_bits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

void expect_denoised(const std::string& path) {
    const OIIO::ImageSpec spec = header(path);
    for (const char* c : {"R", "G", "B", "A", "Noisy.R", "Noisy.G", "Noisy.B"})
        EXPECT_GE(spec.channelindex(c), 0) << path << ": " << c;
    EXPECT_EQ(spec.get_string_attribute("penumbra:denoise"), describe(NforParams{})) << path;
    const std::string estimate = spec.get_string_attribute("penumbra:denoise_relmse_estimate");
    ASSERT_FALSE(estimate.empty()) << path;
    const double e = std::stod(estimate);
    EXPECT_TRUE(std::isfinite(e)) << estimate;
    const std::string stderr_attr =
        spec.get_string_attribute("penumbra:denoise_relmse_estimate_stderr");
    ASSERT_FALSE(stderr_attr.empty()) << path;
    // Reported below its own standard error, the estimate is that error.
    EXPECT_GE(e, std::stod(stderr_attr)) << estimate << " " << stderr_attr;
    const std::string energy = spec.get_string_attribute("penumbra:denoise_firefly_energy");
    ASSERT_FALSE(energy.empty()) << path;
    EXPECT_GE(std::stod(energy), 0) << energy;
    EXPECT_LT(std::stod(energy), 1) << energy;
}

TEST(RenderDenoiseCli, WritesTheDenoisedImageTheNoisyLayerAndTheEstimate) {
    test::ScratchDir dir;
    const test::CliResult r = render({"-q", "-o", dir.file("d.exr"), "--denoise"});
    ASSERT_EQ(r.status, 0) << r.output;
    expect_denoised(dir.file("d.exr"));
    EXPECT_EQ(header(dir.file("d.exr")).nchannels, 7);
    EXPECT_TRUE(std::filesystem::exists(dir.file("d.png")));
    // Without --denoise, none of it.
    ASSERT_EQ(render({"-q", "-o", dir.file("plain.exr"), "--no-preview"}).status, 0);
    const OIIO::ImageSpec plain = header(dir.file("plain.exr"));
    EXPECT_LT(plain.channelindex("Noisy.R"), 0);
    EXPECT_FALSE(plain.find_attribute("penumbra:denoise"));
    // The denoiser changed the image.
    const test::Pixels p = test::read_pixels(dir.file("d.exr"));
    ASSERT_TRUE(p.error.empty()) << p.error;
    EXPECT_FALSE(
        same_bits(channels(p, {"R", "G", "B"}), channels(p, {"Noisy.R", "Noisy.G", "Noisy.B"})));
}

TEST(RenderDenoiseCli, NoisyLayerIsTheRenderWithTheErrorAovsSampleSplit) {
    test::ScratchDir dir;
    ASSERT_EQ(render({"-q", "--no-preview", "-o", dir.file("d.exr"), "--denoise"}).status, 0);
    ASSERT_EQ(render({"-q", "--no-preview", "-o", dir.file("e.exr"), "--aov", "error"}).status, 0);
    const test::Pixels d = test::read_pixels(dir.file("d.exr")),
                       e = test::read_pixels(dir.file("e.exr"));
    ASSERT_TRUE(d.error.empty() && e.error.empty()) << d.error << e.error;
    EXPECT_TRUE(
        same_bits(channels(d, {"Noisy.R", "Noisy.G", "Noisy.B"}), channels(e, {"R", "G", "B"})));
    EXPECT_TRUE(same_bits(channels(d, {"A"}), channels(e, {"A"})));
}

TEST(RenderDenoiseCli, JobFileKeyFramesAndAovs) {
    test::ScratchDir dir;
    const std::string job = dir.write("jobs.json", R"({
      "defaults": {"spp": 2, "width": 24, "denoise": true},
      "jobs": [
        {"scene": ")" + kCornell + R"(", "output": "one.exr"},
        {"scene": ")" + kCornell + R"(", "output": "f_{frame}.exr", "frames": "1-2",
         "aov": "albedo,variance"},
        {"scene": ")" + kCornell + R"(", "output": "off.exr", "denoise": false}
      ]})");
    const test::CliResult r = test::run_penumbra({"render", "--job", job, "--no-preview"});
    ASSERT_EQ(r.status, 0) << r.output;
    for (const char* f : {"one.exr", "f_0001.exr", "f_0002.exr"}) expect_denoised(dir.file(f));
    for (const char* c : {"Albedo.R", "Variance.R"})
        EXPECT_GE(header(dir.file("f_0002.exr")).channelindex(c), 0) << c;
    EXPECT_FALSE(header(dir.file("off.exr")).find_attribute("penumbra:denoise"));
    // The summary table has the estimate's column.
    EXPECT_NE(r.output.find("estimate"), std::string::npos) << r.output;
    const std::string bad =
        dir.write("bad.json", R"({"jobs": [{"scene": "x.gltf", "denoise": "yes"}]})");
    const test::CliResult e = test::run_penumbra({"render", "--job", bad});
    EXPECT_NE(e.status, 0);
    EXPECT_NE(e.output.find("bad.json: jobs[0].denoise: expected true or false"), std::string::npos)
        << e.output;
}

TEST(RenderDenoiseCli, FramesFromTheCommandLineAreEachDenoised) {
    test::ScratchDir dir;
    const test::CliResult r =
        render({"-q", "--no-preview", "--denoise", "--frames", "1-2", "--out-dir", dir.file("")});
    ASSERT_EQ(r.status, 0) << r.output;
    for (const char* f : {"cornell-box_0001.exr", "cornell-box_0002.exr"})
        expect_denoised(dir.file(f));
}

TEST(RenderDenoiseCli, ReferenceMeasuresTheDenoisedAndTheNoisyImage) {
    test::ScratchDir dir;
    ASSERT_EQ(test::run_penumbra({"render", kCornell, "--spp", "32", "--width", "32", "--seed",
                                  "11", "-q", "--no-preview", "-o", dir.file("ref.exr")})
                  .status,
              0);
    const test::CliResult r = render(
        {"--no-preview", "-o", dir.file("d.exr"), "--denoise", "--reference", dir.file("ref.exr")});
    ASSERT_EQ(r.status, 0) << r.output;
    const OIIO::ImageSpec spec = header(dir.file("d.exr"));
    for (const char* key :
         {"penumbra:mse", "penumbra:relmse", "penumbra:noisy_mse", "penumbra:noisy_relmse"})
        EXPECT_TRUE(spec.find_attribute(key)) << key;
    EXPECT_NE(spec.get_float_attribute("penumbra:relmse"),
              spec.get_float_attribute("penumbra:noisy_relmse"));
    EXPECT_NE(r.output.find("denoised in"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("estimated relMSE"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("(noisy: MSE"), std::string::npos) << r.output;
}

// One sample per pixel leaves one half empty: the denoiser would have no variance and no
// cross-validation, so the options are refused before anything renders.
TEST(RenderDenoiseCli, FewerThanTwoSamplesPerPixelIsRefused) {
    test::ScratchDir dir;
    const std::string why = "denoise needs at least 2 samples per pixel, spp is 1";
    const test::CliResult r = test::run_penumbra(
        {"render", kCornell, "--spp", "1", "--width", "8", "--denoise", "-o", dir.file("x.exr")});
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find(why), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("x.exr")));
    const std::string job = dir.write(
        "job.json", R"({"jobs": [{"scene": ")" + kCornell + R"(", "spp": 1, "denoise": true}]})");
    const test::CliResult j = test::run_penumbra({"render", "--job", job});
    EXPECT_NE(j.status, 0);
    EXPECT_NE(j.output.find("jobs[0]: " + why), std::string::npos) << j.output;
    // Two are enough.
    const test::CliResult two =
        test::run_penumbra({"render", kCornell, "--spp", "2", "--width", "8", "--denoise", "-q",
                            "--no-preview", "-o", dir.file("two.exr")});
    EXPECT_EQ(two.status, 0) << two.output;
    expect_denoised(dir.file("two.exr"));
}

// A time limit that runs out in the first pass (of one sample) leaves the raw image: it
// is written as it is, without the denoiser's layer and header fields, and says why.
TEST(RenderDenoiseCli, ARenderStoppedAtOneSampleIsNotDenoised) {
    test::ScratchDir dir;
    const test::CliResult r =
        render({"--no-preview", "--denoise", "--time-limit", "0.000001", "-o", dir.file("t.exr")});
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("not denoised: 1 sample per pixel"), std::string::npos) << r.output;
    const OIIO::ImageSpec spec = header(dir.file("t.exr"));
    EXPECT_EQ(spec.get_string_attribute("penumbra:spp"), "1");
    EXPECT_FALSE(spec.find_attribute("penumbra:denoise"));
    EXPECT_LT(spec.channelindex("Noisy.R"), 0);
}

TEST(RenderDenoiseCli, SameCommandIsBitwiseIdenticalForAnyThreadCount) {
    test::ScratchDir dir;
    const Args base = {"-q", "--no-preview", "--denoise", "--aov", "all"};
    Args one = base, two = base;
    one.insert(one.end(), {"--threads", "1", "-o", dir.file("t1.exr")});
    two.insert(two.end(), {"--threads", "2", "-o", dir.file("t2.exr")});
    ASSERT_EQ(render(one).status, 0);
    ASSERT_EQ(render(two).status, 0);
    auto bytes = [](const std::string& p) {
        std::ifstream f(p, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(f), {});
    };
    const std::string a = bytes(dir.file("t1.exr")), b = bytes(dir.file("t2.exr"));
    ASSERT_FALSE(a.empty());
    EXPECT_TRUE(a == b) << "EXR files differ between --threads 1 and --threads 2";
}

}  // namespace
}  // namespace penumbra
