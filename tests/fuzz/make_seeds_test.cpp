// fuzz/make_seeds.py: the real files of ../shared/scenes/wild become self-contained seeds
// (external buffers and images inlined, since the fuzz target's input stands alone, and
// images scaled down to 64 pixels a side with their buffers repacked), each of which loads
// (or names the compression extension it needs), and seeds over the size limit are left
// out.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "core/error.h"
#include "io/gltf/gltf_loader.h"
#include "support/gltf_builder.h"
#include "support/paths.h"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

TEST(MakeSeeds, WildFilesBecomeSelfContainedSeedsThatLoad) {
    const test::ScratchDir dir;
    const std::string out = dir.file("seeds");
    const std::string cmd = std::string("python3 ") + PENUMBRA_SOURCE_DIR +
                            "/fuzz/make_seeds.py '" + out + "' '" +
                            test::shared_path("scenes/wild") + "' --max-bytes 1048576 >/dev/null";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    size_t seeds = 0;
    for (const auto& e : fs::directory_iterator(out)) {
        ++seeds;
        EXPECT_LE(fs::file_size(e.path()), 1u << 20) << e.path();
        // A seed is the only file the fuzz target has: copied away from its folder, it
        // must still load (every wild file renders).
        const std::string alone = dir.file("alone" + e.path().extension().string());
        fs::copy_file(e.path(), alone, fs::copy_options::overwrite_existing);
        testing::internal::CaptureStderr();
        try {
            load_gltf(alone);
        } catch (const SceneError& err) {
            // Draco and meshopt files (Pirate) until their decoders land; nothing else.
            EXPECT_NE(std::string(err.what()).find("extensionsRequired: unsupported extension"),
                      std::string::npos)
                << e.path().filename() << ": " << err.what();
        }
        testing::internal::GetCapturedStderr();
    }
    // Each .gltf gives a .gltf and a .glb seed; over 1 MiB (FlightHelmet, whose 3 MB
    // of geometry stays) are left out.
    EXPECT_TRUE(fs::exists(out + "/CesiumBoxWebp_CesiumBoxWebp-Required.glb"));
    EXPECT_TRUE(fs::exists(out + "/Fox_Fox.glb"));
    EXPECT_TRUE(fs::exists(out + "/UnlitTest_UnlitTest.gltf"));  // its UnlitTest.bin inlined
    EXPECT_FALSE(fs::exists(out + "/FlightHelmet_FlightHelmet.gltf"));
    // Scaled-down images make these fit: SpecGlossVsMetalRough's five 2048x2048 PNGs
    // (15 MB), in the .gltf (data: URIs) and the .glb made from it, and the 1.7 MB of
    // images in NormalTangentTest.glb's BIN chunk, which is repacked. The scaling needs
    // oiiotool (openimageio-tools, which scripts/setup.sh installs).
    if (std::system("command -v oiiotool >/dev/null") != 0)
        GTEST_SKIP() << "no oiiotool: seed images are not scaled down";
    for (const char* name : {"/SpecGlossVsMetalRough_SpecGlossVsMetalRough.gltf",
                             "/SpecGlossVsMetalRough_SpecGlossVsMetalRough.glb",
                             "/NormalTangentTest_NormalTangentTest.glb"}) {
        ASSERT_TRUE(fs::exists(out + name)) << name;
        EXPECT_LT(fs::file_size(out + name), 256u << 10) << name;
    }
    EXPECT_GE(seeds, 10u);
}

}  // namespace
}  // namespace penumbra
