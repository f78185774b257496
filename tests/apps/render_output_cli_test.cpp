// The render command's colour and EXR options end to end: AOV layers, half, compression,
// working and output spaces, preview view, reference error, timing, and that the same
// command with AOVs still gives a bitwise identical file for any thread count.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>

#include "support/cli_process.h"
#include "support/gltf_builder.h"
#include "support/paths.h"

namespace penumbra {
namespace {

using Args = std::vector<std::string>;

// penumbra render on the Cornell box, small, plus `more`.
test::CliResult render(const Args& more) {
    Args args = {"render", test::source_path("scenes/cornell-box.gltf"), "--spp", "2", "--width",
                 "32"};
    args.insert(args.end(), more.begin(), more.end());
    return test::run_penumbra(args);
}

std::string read_file(const std::string& p) {
    std::ifstream f(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(f), {});
}

OIIO::ImageSpec header(const std::string& path) {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    EXPECT_TRUE(in) << OIIO::geterror();
    return in ? in->spec() : OIIO::ImageSpec();
}

TEST(RenderOutputCli, AovsHalfCompressionAndAcesSpaces) {
    test::ScratchDir dir;
    const test::CliResult r =
        render({"-q", "-o", dir.file("a.exr"), "--aov", "albedo,depth,samples", "--half",
                "--compression", "dwaa", "--working-space", "ACEScg", "--output-colorspace",
                "ACES2065-1", "--view", "ACES 1.0 - SDR Video"});
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(std::filesystem::exists(dir.file("a.png")));
    const OIIO::ImageSpec spec = header(dir.file("a.exr"));
    for (const char* c :
         {"R", "G", "B", "A", "Albedo.R", "Albedo.G", "Albedo.B", "Depth.Z", "Samples.X"})
        EXPECT_GE(spec.channelindex(c), 0) << c;
    EXPECT_EQ(spec.nchannels, 9);
    EXPECT_EQ(spec.channelformats.at(size_t(spec.channelindex("R"))), OIIO::TypeDesc::HALF);
    EXPECT_EQ(spec.channelformats.at(size_t(spec.channelindex("Depth.Z"))), OIIO::TypeDesc::FLOAT);
    EXPECT_EQ(spec.get_string_attribute("compression"), "dwaa");
    EXPECT_EQ(spec.get_string_attribute("penumbra:colorspace"), "ACES2065-1");
    EXPECT_EQ(spec.get_string_attribute("penumbra:working_space"), "ACEScg");
    EXPECT_EQ(spec.get_string_attribute("penumbra:camera"), "front");
    const OIIO::ParamValue* chroma = spec.find_attribute("chromaticities");
    ASSERT_TRUE(chroma);
    EXPECT_NEAR(static_cast<const float*>(chroma->data())[0], 0.7347f, 1e-6f);  // AP0 red x
    EXPECT_TRUE(spec.find_attribute("worldtocamera"));
    EXPECT_TRUE(spec.find_attribute("worldtoNDC"));
    EXPECT_FALSE(spec.find_attribute("penumbra:render_seconds"));  // opt-in
    // What made the image: the program, the scene, how it was traced.
    const std::string software = spec.get_string_attribute("Software");
    EXPECT_EQ(software.rfind("penumbra ", 0), 0u) << software;
    EXPECT_EQ(spec.get_string_attribute("penumbra:scene"),
              test::source_path("scenes/cornell-box.gltf"));
    EXPECT_EQ(spec.get_string_attribute("penumbra:accelerator"), "embree");
    EXPECT_EQ(spec.get_string_attribute("penumbra:integrator"), "path");
    EXPECT_EQ(spec.get_string_attribute("penumbra:spp"), "2");
    // At least one camera ray per sample of the 32 x 32 image at 2 spp.
    EXPECT_GE(std::stoull(std::string(spec.get_string_attribute("penumbra:rays", "0"))), 32u * 32u * 2u);
    EXPECT_EQ(spec.get_string_attribute("penumbra:nonfinite_samples"), "0");
}

TEST(RenderOutputCli, SameCommandWithAovsIsBitwiseIdenticalForAnyThreadCount) {
    test::ScratchDir dir;
    const Args base = {"--seed", "5", "-q", "--no-preview", "--aov", "all"};
    Args one = base, two = base;
    one.insert(one.end(), {"--threads", "1", "-o", dir.file("t1.exr")});
    two.insert(two.end(), {"--threads", "2", "-o", dir.file("t2.exr")});
    ASSERT_EQ(render(one).status, 0);
    ASSERT_EQ(render(two).status, 0);
    const std::string a = read_file(dir.file("t1.exr")), b = read_file(dir.file("t2.exr"));
    ASSERT_FALSE(a.empty());
    EXPECT_TRUE(a == b) << "EXR files differ between --threads 1 and --threads 2";
}

TEST(RenderOutputCli, AdaptiveAndFireflyOptionsGoIntoTheFile) {
    test::ScratchDir dir;
    // Off by default: none of their header fields.
    ASSERT_EQ(render({"-q", "--no-preview", "-o", dir.file("plain.exr")}).status, 0);
    const OIIO::ImageSpec plain = header(dir.file("plain.exr"));
    for (const char* key : {"penumbra:target_error", "penumbra:clamp_direct",
                            "penumbra:clamp_indirect", "penumbra:regularize"})
        EXPECT_FALSE(plain.find_attribute(key)) << key;
    const Args adaptive = {"render", test::source_path("scenes/cornell-box.gltf"), "--width",
                           "32", "-q", "--no-preview", "--spp", "64", "--target-error", "0.5",
                           "--clamp-indirect", "10", "--regularize", "0.2"};
    Args one = adaptive, two = adaptive;
    one.insert(one.end(), {"--threads", "1", "-o", dir.file("a1.exr")});
    two.insert(two.end(), {"--threads", "2", "-o", dir.file("a2.exr")});
    ASSERT_EQ(test::run_penumbra(one).status, 0) << test::run_penumbra(one).output;
    ASSERT_EQ(test::run_penumbra(two).status, 0);
    EXPECT_TRUE(read_file(dir.file("a1.exr")) == read_file(dir.file("a2.exr")))
        << "adaptive EXR files differ between --threads 1 and --threads 2";
    const OIIO::ImageSpec spec = header(dir.file("a1.exr"));
    for (const char* c : {"Error.X", "Samples.X"}) EXPECT_GE(spec.channelindex(c), 0) << c;
    EXPECT_EQ(spec.get_string_attribute("penumbra:target_error"), "0.500000");
    EXPECT_EQ(spec.get_string_attribute("penumbra:clamp_indirect"), "10.000000");
    EXPECT_EQ(spec.get_string_attribute("penumbra:regularize"), "0.200000");
    EXPECT_FALSE(spec.find_attribute("penumbra:clamp_direct"));
    const double mean_spp = std::stod(spec.get_string_attribute("penumbra:mean_spp", "0"));
    EXPECT_GE(mean_spp, 20.0);  // the minimum for E = 0.5: 16 / 0.5^0.3 = 19.7, even
    EXPECT_LE(mean_spp, 64.0);
    EXPECT_TRUE(spec.find_attribute("penumbra:unconverged_pixels"));
}

TEST(RenderOutputCli, TimingAndReferenceGoIntoTheHeader) {
    test::ScratchDir dir;
    ASSERT_EQ(render({"-q", "--no-preview", "-o", dir.file("ref.exr")}).status, 0);
    const test::CliResult r = render({"--seed", "9", "--no-preview", "--timing-metadata", "-o",
                                      dir.file("x.exr"), "--reference", dir.file("ref.exr")});
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("relMSE"), std::string::npos) << r.output;
    const OIIO::ImageSpec spec = header(dir.file("x.exr"));
    EXPECT_GT(spec.get_float_attribute("penumbra:render_seconds"), 0);
    EXPECT_GT(spec.get_float_attribute("penumbra:mse"), 0);  // another seed: not equal
    EXPECT_GT(spec.get_float_attribute("penumbra:relmse"), 0);
    EXPECT_EQ(spec.get_string_attribute("penumbra:reference"), dir.file("ref.exr"));
}

TEST(RenderOutputCli, BadColourChoicesFailBeforeRendering) {
    test::ScratchDir dir;
    test::CliResult r = render({"-o", dir.file("v.exr"), "--view", "Filmic"});
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("--view 'Filmic'"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("Standard"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("v.exr")));
    r = render({"-o", dir.file("v.exr"), "--aov", "albedo,glow"});
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("glow"), std::string::npos) << r.output;
    r = render({"-o", dir.file("v.exr"), "--compression", "lzw"});
    EXPECT_NE(r.status, 0);
}

}  // namespace
}  // namespace penumbra
