// scripts/make_many_lights.py: its 10,000 emissive triangles load and render as the scene's
// only lighting (the count and determinism are checked in
// tests/scripts/crosscheck/efficiency_metrics_test.py).
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

TEST(MakeManyLights, TenThousandEmittersLightTheSceneAtOneSpp) {
    const test::ScratchDir dir;
    const std::string scene = dir.file("many-lights.gltf");
    const std::string cmd =
        "python3 '" + test::source_path("scripts/make_many_lights.py") + "' '" + scene + "'";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    const std::string exr = dir.file("many-lights.exr");
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

}  // namespace
}  // namespace penumbra
