// scripts/crosscheck/efficiency.py's measures (relMSE, efficiency, the reference-error
// correction, image reading, Cycles' timing lines) through its Python unit tests on
// synthetic images, and its Lambertian Cornell box, whose smooth sphere shows shadow
// rays from lifted origins blocked by the area light they are aimed at (spawn_ray).
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

TEST(EfficiencyHarness, MetricsPassTheirUnitTestsOnSyntheticImages) {
    const std::string cmd = "cd '" + test::source_path("tests/scripts/crosscheck") +
                            "' && python3 -m unittest -q efficiency_metrics_test 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
}

// Mean red of the sphere's upper half (x 17-21, y 13-15 of 32 x 32), direct light only.
float sphere_top(const test::ScratchDir& dir, const std::string& scene, const std::string& strategy,
                 const std::string& spp) {
    const std::string exr = dir.file(strategy + ".exr");
    const test::CliResult r = test::run_penumbra(
        {"render", scene, "-o", exr, "--width", "32", "--spp", spp, "--max-depth", "1",
         "--strategy", strategy, "--filter", "box", "--no-default-light", "--no-preview", "-q"});
    EXPECT_EQ(r.status, 0) << r.output;
    const OIIO::ImageBuf image(exr);
    const auto stats = OIIO::ImageBufAlgo::computePixelStats(
        OIIO::ImageBufAlgo::cut(image, OIIO::ROI(17, 22, 13, 16)));
    return stats.avg.empty() ? 0.0f : float(stats.avg[0]);
}

TEST(EfficiencyHarness, LambertianCornellSphereGetsTheSameDirectLightFromBothEstimators) {
    // Light sampling alone and BSDF sampling alone estimate the same direct light. Shadow
    // rays blocked by the light they aim at make light sampling give 0.37x BSDF sampling's
    // value here; BSDF sampling at 1024 spp is good to about 5% over these 15 pixels, so
    // the 15% bound sees a bias of that order and not noise.
    const test::ScratchDir dir;
    const std::string scene = dir.file("cornell-lambertian.gltf");
    const std::string cmd = "cd '" + test::source_path("scripts/crosscheck") +
                            "' && python3 -c \"import efficiency_scenes as s; "
                            "s.lambertian_cornell('" +
                            scene + "')\"";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    const float light = sphere_top(dir, scene, "light", "64");
    const float bsdf = sphere_top(dir, scene, "bsdf", "1024");
    ASSERT_GT(bsdf, 0.1f);
    EXPECT_NEAR(light / bsdf, 1.0f, 0.15f)
        << "light sampling " << light << ", BSDF sampling " << bsdf;
}

TEST(EfficiencyHarness, EmbreeTutorialSceneConvertsToTheSameView) {
    // embree_cornell.py turns the tutorial's OBJ, point light and camera into glTF: the
    // render must show the room as the tutorial does (red wall left, green right, lit
    // floor below), so that the equal-spp comparison times the same picture.
    const std::string ecs = "/usr/share/doc/embree3/models/cornell_box.ecs";
    if (std::system(("test -f " + ecs).c_str()) != 0)
        GTEST_SKIP() << ecs << " is missing (Debian's embree-tools, scripts/setup.sh --test)";
    const test::ScratchDir dir;
    const std::string scene = dir.file("embree-cornell.gltf");
    const std::string cmd = "python3 '" + test::source_path("scripts/crosscheck/embree_cornell.py") +
                            "' '" + scene + "'";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    const std::string exr = dir.file("e.exr");
    const test::CliResult r = test::run_penumbra(
        {"render", scene, "-o", exr, "--width", "32", "--spp", "16", "--max-depth", "1",
         "--no-default-light", "--no-preview", "-q"});
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(r.output.find("warning"), std::string::npos) << r.output;
    const OIIO::ImageBuf image(exr);
    auto mean = [&](int x0, int x1, int y0, int y1) {
        return OIIO::ImageBufAlgo::computePixelStats(
                   OIIO::ImageBufAlgo::cut(image, OIIO::ROI(x0, x1, y0, y1)))
            .avg;
    };
    const auto left = mean(1, 4, 8, 24), right = mean(28, 31, 8, 24), floor = mean(4, 10, 27, 31);
    ASSERT_GE(left.size(), 3u);
    EXPECT_GT(left[0], 10 * (left[1] + left[2] + 1e-3f)) << "the left wall is not red";
    EXPECT_GT(right[1], 10 * (right[0] + right[2] + 1e-3f)) << "the right wall is not green";
    EXPECT_GT(floor[0], 0.05f) << "the floor is unlit";
}

}  // namespace
}  // namespace penumbra
