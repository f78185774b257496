// scripts/make_many_lights.py: each layout's 10,000 emissive triangles load and render as the
// scene's only lighting (counts, determinism, levels and facing are checked by
// tests/scripts/make_many_lights_test.py, which this runs).
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "support/cli_process.h"
#include "support/gltf_builder.h"
#include "support/paths.h"

namespace penumbra {
namespace {

TEST(MakeManyLights, LayoutsPassTheirUnitTests) {
    const std::string cmd = "cd '" + test::source_path("tests/scripts") +
                            "' && python3 -m unittest -q make_many_lights_test 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
}

class MakeManyLightsLayout : public testing::TestWithParam<const char*> {};

TEST_P(MakeManyLightsLayout, TenThousandEmittersLightTheSceneAtOneSpp) {
    const test::ScratchDir dir;
    const std::string layout = GetParam();
    const std::string scene = dir.file(layout + ".gltf");
    const std::string cmd = "python3 '" + test::source_path("scripts/make_many_lights.py") +
                            "' '" + scene + "' --layout " + layout;
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    const std::string exr = dir.file(layout + ".exr");
    const test::CliResult r = test::run_penumbra(
        {"render", scene, "-o", exr, "--spp", "1", "--width", "32", "--no-preview"});
    ASSERT_EQ(r.status, 0) << r.output;
    // --default-light auto finds the emitters bright enough to light the scene alone.
    EXPECT_NE(r.output.find("lighting: the file's emitters"), std::string::npos) << r.output;
    // Lit only by the emitters (no default lights, black environment): not black.
    const OIIO::ImageBuf image(exr);
    const auto stats = OIIO::ImageBufAlgo::computePixelStats(image);
    ASSERT_GE(stats.avg.size(), 3u);
    EXPECT_GT(stats.avg[0] + stats.avg[1] + stats.avg[2], 0.1) << r.output;
    EXPECT_EQ(stats.nancount[0] + stats.infcount[0], 0u);
}

INSTANTIATE_TEST_SUITE_P(MakeManyLights, MakeManyLightsLayout,
                         testing::Values("cloud", "dome", "hall"),
                         [](const testing::TestParamInfo<const char*>& info) {
                             return std::string(info.param);
                         });

}  // namespace
}  // namespace penumbra
