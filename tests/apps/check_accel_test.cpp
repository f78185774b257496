// End-to-end tests of `penumbra check-accel`.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "support/cli_process.h"
#include "support/paths.h"

namespace penumbra {
namespace {

// penumbra with a whitespace-separated argument string (no argument here has spaces).
test::CliResult run_penumbra(const std::string& args) {
    std::istringstream in(args);
    std::vector<std::string> argv;
    for (std::string a; in >> a;) argv.push_back(a);
    return test::run_penumbra(argv);
}

TEST(CheckAccelCli, CornellBoxPassesAndReportsEveryAccelerator) {
    const test::CliResult r = run_penumbra("check-accel " + test::source_path("scenes/cornell-box.gltf") +
                                  " --rays 5000 --width 48 --images --spp 1");
    ASSERT_EQ(r.status, 0) << r.output;
    for (const char* name : {"embree", "bvh-sah", "bvh-median", "bvh-center", "grid"})
        EXPECT_NE(r.output.find(name), std::string::npos) << name << "\n" << r.output;
    EXPECT_NE(r.output.find("Mrays/s"), std::string::npos);
    EXPECT_NE(r.output.find("edge/vertex"), std::string::npos);
    EXPECT_NE(r.output.find("pixels differ"), std::string::npos);
    EXPECT_NE(r.output.find("PASS"), std::string::npos);
}

// The bundled instancing and motion-blur scenes pass at the default threshold with the
// default ray counts (365,536 rays; on instances.gltf Embree's float instance transform
// loses a few edge cases that double precision gives to our BVH, which are not counted).
TEST(CheckAccelCli, InstancedAndMovingScenesPass) {
    const test::CliResult inst = run_penumbra("check-accel " + test::source_path("scenes/instances.gltf"));
    ASSERT_EQ(inst.status, 0) << inst.output;
    EXPECT_NE(inst.output.find("PASS"), std::string::npos);
    const test::CliResult moving = run_penumbra("check-accel " + test::source_path("scenes/motion-blur.gltf") +
                                       " --shutter-open 0.5 --shutter-close 1 --rays 40000");
    ASSERT_EQ(moving.status, 0) << moving.output;
    EXPECT_NE(moving.output.find("PASS"), std::string::npos);
}

TEST(CheckAccelCli, RejectsBadInput) {
    EXPECT_NE(run_penumbra("check-accel /nonexistent.gltf").status, 0);
    EXPECT_NE(run_penumbra("check-accel " + test::source_path("scenes/cornell-box.gltf") +
                           " --threshold 2")
                  .status,
              0);
}

}  // namespace
}  // namespace penumbra
