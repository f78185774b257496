// Every scene that ships in scenes/ (and scenes/hard/) loads and renders: small, few
// samples, through `penumbra render` (default camera and lights where the file has
// none), with no NaN or Inf and no warning; the showcase scenes in scenes/ must also
// show some light (the hard cases may be dark at 2 spp: tiny lights, shadowed planes).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include "support/cli_process.h"
#include "support/gltf_builder.h"
#include "support/paths.h"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> bundled_scenes(const char* dir) {
    std::vector<std::string> files;
    const fs::path d = test::source_path(dir);
    if (!fs::exists(d)) return files;
    for (const auto& e : fs::directory_iterator(d))
        if (e.path().extension() == ".gltf" || e.path().extension() == ".glb")
            files.push_back(e.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

void expect_render_finite(const std::vector<std::string>& scenes, bool lit) {
    const test::ScratchDir dir;
    for (const std::string& scene : scenes) {
        const std::string out = dir.file(fs::path(scene).stem().string() + ".exr");
        const test::CliResult r = test::run_penumbra(
            {"render", scene, "-o", out, "--width", "24", "--spp", "2", "--no-preview", "-q"});
        ASSERT_EQ(r.status, 0) << scene << "\n" << r.output;
        OIIO::ImageBuf img(out);
        ASSERT_TRUE(img.read()) << scene << ": " << img.geterror();
        const auto stats = OIIO::ImageBufAlgo::computePixelStats(img);
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(stats.nancount[c], 0u) << scene;
            EXPECT_EQ(stats.infcount[c], 0u) << scene;
        }
        if (lit) EXPECT_GT(stats.max[0] + stats.max[1] + stats.max[2], 0.0f) << scene << ": black";
        EXPECT_EQ(r.output.find("warning"), std::string::npos) << scene << "\n" << r.output;
    }
}

TEST(BundledScenes, ShowcaseScenesRenderFiniteAndLit) {
    const std::vector<std::string> scenes = bundled_scenes("scenes");
    ASSERT_GE(scenes.size(), 8u);  // cornell x2, material-spheres, instances, dof, ...
    expect_render_finite(scenes, true);
}

TEST(BundledScenes, HardCasesRenderFinite) {
    const std::vector<std::string> scenes = bundled_scenes("scenes/hard");
    ASSERT_FALSE(scenes.empty());
    expect_render_finite(scenes, false);
}

}  // namespace
}  // namespace penumbra
