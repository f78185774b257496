// `penumbra render --accel`: every accelerator renders the same image from the same
// samples, to float rounding (a few pixels may differ where a ray grazes an edge:
// check-accel's territory).
#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include "support/cli_process.h"
#include "support/gltf_builder.h"
#include "support/paths.h"

namespace penumbra {
namespace {

TEST(RenderAccelCli, EveryAcceleratorRendersTheSameImage) {
    const test::ScratchDir dir;
    auto render = [&](const std::string& accel) {
        const std::string out = dir.file(accel + ".exr");
        const test::CliResult r =
            test::run_penumbra({"render", test::source_path("scenes/cornell-box.gltf"), "-o", out,
                                "--width", "32", "--spp", "4", "--accel", accel, "--no-preview",
                                "-q"});
        EXPECT_EQ(r.status, 0) << r.output;
        return out;
    };
    const OIIO::ImageBuf embree(render("embree"));
    for (const char* accel : {"bvh", "bvh-median", "bvh-center", "grid"}) {
        const std::string path = render(accel);
        const OIIO::ImageBuf other(path);
        // Hit points agree to float rounding (measured: mean 3e-8, max 5e-6 on values
        // of 0.1 to 1), which moves pixels by far less than 1e-4; a path that goes another
        // way changes its pixel by a sample's worth, far more. At most 1% may.
        const auto cmp = OIIO::ImageBufAlgo::compare(embree, other, 1e-4f, 1e-4f);
        EXPECT_FALSE(cmp.error) << accel;
        EXPECT_LE(cmp.nfail, 32u * 32u / 100) << accel << ": " << cmp.nfail << " pixels differ";
        EXPECT_LT(cmp.meanerror, 1e-5) << accel;
    }
}

}  // namespace
}  // namespace penumbra
