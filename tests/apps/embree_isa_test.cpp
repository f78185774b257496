// Images that do not depend on Embree's code path: bundled and real scenes (static,
// moving, instanced, alpha-masked, skinned, compressed) rendered under every Embree ISA
// this CPU runs (PENUMBRA_EMBREE_CONFIG=isa=...), and with glibc's FMA variants of its
// maths functions switched off, give the same EXR pixels, bit for bit.
// EmbreeAccel recomputes every hit with our own arithmetic; only the choice of triangle
// on exact ties (coincident faces, a ray within rounding of a shared edge) is Embree's,
// and none of these renders meets one (docs/conventions.md has the measured rates).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/cli_process.h"
#include "support/embree_isas.h"
#include "support/exr_pixels.h"
#include "support/gltf_builder.h"
#include "support/paths.h"

namespace penumbra {
namespace {

struct IsaScene {
    std::string name, path;
    std::vector<std::string> args;  // beyond size and samples
};

std::vector<IsaScene> isa_scenes() {
    const std::vector<std::string> blur = {"--shutter-open", "0.5", "--shutter-close", "1"};
    return {
        {"cornell", test::source_path("scenes/cornell-box.gltf"), {}},
        {"motion", test::source_path("scenes/motion-blur.gltf"), blur},
        {"instances", test::source_path("scenes/instances.gltf"), {}},
        {"dof", test::source_path("scenes/dof.gltf"), {}},
        {"box_animated",
         test::shared_path("scenes/khronos/BoxAnimated.gltf"),
         {"--shutter-open", "0", "--shutter-close", "0.5"}},
        {"flight_helmet", test::shared_path("scenes/wild/FlightHelmet/FlightHelmet.gltf"), {}},
        {"golf_ball", test::shared_path("scenes/wild/GolfBall/GolfBall.glb"), {}},
        {"chess_board", test::shared_path("scenes/wild/ChessBoard/chess-board.glb"), {}},
        {"fox", test::shared_path("scenes/wild/Fox/Fox.glb"), {"--time", "0.4"}},
    };
}

TEST(EmbreeIsa, RendersAreBitwiseIdenticalUnderEveryIsa) {
    const std::vector<std::string> isas = test::embree_isas();
    ASSERT_FALSE(isas.empty()) << "an x86-64 CPU without SSE4.2";
    RecordProperty("isas", [&] {
        std::string s;
        for (const std::string& i : isas) s += (s.empty() ? "" : ",") + i;
        return s;
    }());
    const test::ScratchDir dir;
    for (const IsaScene& scene : isa_scenes()) {
        std::vector<std::string> outputs;
        for (const std::string& isa : isas) {
            const test::ScopedEmbreeIsa use(isa);
            const std::string out = dir.file(scene.name + "_" + isa + ".exr");
            std::vector<std::string> args = {"render", scene.path, "-o", out,  "--width",
                                             "96",     "--spp",    "8",  "-q", "--no-preview"};
            args.insert(args.end(), scene.args.begin(), scene.args.end());
            const test::CliResult r = test::run_penumbra(args);
            ASSERT_EQ(r.status, 0) << scene.name << " under " << isa << ": " << r.output;
            outputs.push_back(out);
        }
        // glibc picks FMA or SSE2 variants of its maths functions at run time, and some
        // round differently for a few arguments (docs/conventions.md): the widest ISA
        // again with glibc's FMA and AVX2 variants switched off.
        {
            const test::ScopedEmbreeIsa use(isas.back());
            setenv("GLIBC_TUNABLES", "glibc.cpu.hwcaps=-AVX2,-FMA", 1);
            const std::string out = dir.file(scene.name + "_nofma.exr");
            std::vector<std::string> args = {"render", scene.path, "-o", out,  "--width",
                                             "96",     "--spp",    "8",  "-q", "--no-preview"};
            args.insert(args.end(), scene.args.begin(), scene.args.end());
            const test::CliResult r = test::run_penumbra(args);
            unsetenv("GLIBC_TUNABLES");
            ASSERT_EQ(r.status, 0) << scene.name << " without FMA libm: " << r.output;
            EXPECT_TRUE(test::same_pixels(outputs[0], out)) << scene.name << ": glibc without FMA";
        }
        for (size_t i = 1; i < outputs.size(); ++i)
            EXPECT_TRUE(test::same_pixels(outputs[0], outputs[i]))
                << scene.name << ": " << isas[0] << " against " << isas[i];
    }
}

// The variable reaches Embree's device: with isa=sse4.2 Embree reports SSE4.2 as the
// widest instruction set it runs (its "Config" section under verbose=1).
TEST(EmbreeIsa, TheConfigReachesEmbree) {
    const test::ScratchDir dir;
    setenv("PENUMBRA_EMBREE_CONFIG", "isa=sse4.2,verbose=1", 1);
    const test::CliResult r =
        test::run_penumbra({"render", test::source_path("scenes/cornell-box.gltf"), "-o",
                            dir.file("x.exr"), "--width", "16", "--spp", "1", "-q"});
    unsetenv("PENUMBRA_EMBREE_CONFIG");
    ASSERT_EQ(r.status, 0) << r.output;
    const size_t config = r.output.find("Config");
    ASSERT_NE(config, std::string::npos) << r.output;
    const size_t targets = r.output.find("Targets", config);
    ASSERT_NE(targets, std::string::npos) << r.output;
    const std::string line = r.output.substr(targets, r.output.find('\n', targets) - targets);
    EXPECT_NE(line.find("SSE4.2"), std::string::npos) << line;
    EXPECT_EQ(line.find("AVX"), std::string::npos) << line;
}

}  // namespace
}  // namespace penumbra
