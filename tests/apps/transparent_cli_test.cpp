// `render --transparent-background` and the ID layers end to end, on a file with known
// geometry (support/two_quads_scene.h) and a box filter: quad A (node 1, material 0) over
// columns 0-5 and quad B (node 2, no material) over columns 6-11, both over rows 4-15; the
// rest is background. The EXR's alpha is
// the coverage and its colour 0 where nothing is; ObjectID.X and MaterialID.X are 32-bit floats
// (even with --half) holding the nodes' and materials' indices; the header records the option; the
// PNG preview carries the alpha; a denoised render keeps the film's alpha; and the farm's bands
// merge to the bits of one machine.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "core/film/cryptomatte.h"
#include "support/cli_process.h"
#include "support/exr_pixels.h"
#include "support/gltf_builder.h"
#include "support/two_quads_scene.h"

namespace penumbra {
namespace {

using Args = std::vector<std::string>;

Args render_args(const std::string& scene, const std::string& out, const Args& more) {
    Args args = {"render", scene, "-o", out, "--width", "16", "--height", "16", "--spp", "4"};
    for (const char* a : {"--env-color", "1", "1", "1", "--filter", "box", "-q"}) args.push_back(a);
    args.insert(args.end(), more.begin(), more.end());
    return args;
}

// The value of channel `name` at (x, y).
float at(const test::Pixels& p, const std::string& name, int x, int y) {
    const auto it = std::find(p.channels.begin(), p.channels.end(), name);
    if (it == p.channels.end()) {
        ADD_FAILURE() << "no channel " << name;
        return -100;
    }
    const size_t c = size_t(it - p.channels.begin());
    return p.data[(size_t(y) * p.width + x) * p.channels.size() + c];
}

TEST(TransparentCli, AlphaIsCoverageAndIdLayersHoldNodesAndMaterials) {
    const test::ScratchDir dir;
    const std::string scene = test::write_two_quads(dir), exr = dir.file("t.exr");
    const test::CliResult r = test::run_penumbra(render_args(
        scene, exr, {"--transparent-background", "--aov", "object_id,material_id", "--half"}));
    ASSERT_EQ(r.status, 0) << r.output;
    const test::Pixels p = test::read_pixels(exr);
    ASSERT_TRUE(p.error.empty()) << p.error;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            const bool miss = y < 4 || x >= 12, a = x < 6;
            EXPECT_EQ(at(p, "A", x, y), miss ? 0.0f : 1.0f) << x << "," << y;
            if (miss)
                for (const char* c : {"R", "G", "B"}) EXPECT_EQ(at(p, c, x, y), 0.0f);
            else
                EXPECT_GT(at(p, "R", x, y), 0.1f);
            EXPECT_EQ(at(p, "ObjectID.X", x, y), miss ? -1.0f : a ? 1.0f : 2.0f) << x << "," << y;
            EXPECT_EQ(at(p, "MaterialID.X", x, y), miss ? -1.0f
                                                   : a  ? 0.0f
                                                        : -2.0f)
                << x << "," << y;
        }
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(exr);
    ASSERT_TRUE(in);
    const OIIO::ImageSpec& spec = in->spec();
    EXPECT_EQ(spec.get_string_attribute("penumbra:transparent_background"), "1");
    for (const char* c : {"ObjectID.X", "MaterialID.X"})
        EXPECT_EQ(spec.channelformat(spec.channelindex(c)), OIIO::TypeDesc::FLOAT) << c;
    EXPECT_EQ(spec.channelformat(spec.channelindex("R")), OIIO::TypeDesc::HALF);
    // The preview: straight colour with the alpha.
    OIIO::ImageSpec straight;  // the file's bytes, not premultiplied while reading
    straight.attribute("oiio:UnassociatedAlpha", 1);
    std::unique_ptr<OIIO::ImageInput> png = OIIO::ImageInput::open(dir.file("t.png"), &straight);
    ASSERT_TRUE(png);
    ASSERT_EQ(png->spec().nchannels, 4);
    std::vector<unsigned char> bytes(16 * 16 * 4);
    ASSERT_TRUE(png->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, bytes.data()));
    EXPECT_EQ(bytes[(0 * 16 + 0) * 4 + 3], 0);    // background
    EXPECT_EQ(bytes[(8 * 16 + 2) * 4 + 3], 255);  // quad A
    EXPECT_GT(bytes[(8 * 16 + 2) * 4 + 0], 100);  // its colour, not premultiplied
}

TEST(TransparentCli, CryptomatteLayersRankTheNamesHashesWithTheirCoverage) {
    const test::ScratchDir dir;
    const std::string scene = test::write_two_quads(dir), exr = dir.file("c.exr");
    const test::CliResult r = test::run_penumbra(
        render_args(scene, exr, {"--aov", "cryptomatte", "--half", "--no-preview"}));
    ASSERT_EQ(r.status, 0) << r.output;
    const test::Pixels p = test::read_pixels(exr);
    const float left = cryptomatte_float(cryptomatte_hash("left")),
                right = cryptomatte_float(cryptomatte_hash("right")),
                grey = cryptomatte_float(cryptomatte_hash("grey")),
                plain = cryptomatte_float(cryptomatte_hash("default"));
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            const bool miss = test::two_quads_miss(x, y), l = test::two_quads_left(x, y);
            // Every sample of a pixel sees one quad or none (box filter, edges on pixel
            // borders): rank 0 covers it all, the other ranks are empty.
            EXPECT_EQ(at(p, "CryptoObject00.R", x, y), miss ? 0 : l ? left : right);
            EXPECT_EQ(at(p, "CryptoObject00.G", x, y), miss ? 0.0f : 1.0f);
            EXPECT_EQ(at(p, "CryptoMaterial00.R", x, y), miss ? 0 : l ? grey : plain);
            EXPECT_EQ(at(p, "CryptoObject00.B", x, y), 0.0f);
            EXPECT_EQ(at(p, "CryptoMaterial02.A", x, y), 0.0f);
        }
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(exr);
    ASSERT_TRUE(in);
    const OIIO::ImageSpec& spec = in->spec();
    EXPECT_EQ(spec.get_string_attribute(cryptomatte_key("CryptoObject", "name")), "CryptoObject");
    const std::string manifest =
        spec.get_string_attribute(cryptomatte_key("CryptoObject", "manifest"));
    char left_hex[16];
    std::snprintf(left_hex, sizeof left_hex, "%08x", cryptomatte_hash("left"));
    EXPECT_NE(manifest.find("\"left\":\"" + std::string(left_hex) + "\""), std::string::npos)
        << manifest;
    EXPECT_NE(manifest.find("\"right\":"), std::string::npos) << manifest;
    EXPECT_NE(spec.get_string_attribute(cryptomatte_key("CryptoMaterial", "manifest"))
                  .find("\"default\":\"42c9679f\""),
              std::string::npos);
    // IDs stay 32-bit under --half.
    EXPECT_EQ(spec.channelformat(spec.channelindex("CryptoObject00.R")), OIIO::TypeDesc::FLOAT);
}

TEST(TransparentCli, WithoutTheOptionAlphaIsOneAndThePreviewRgb) {
    const test::ScratchDir dir;
    const std::string scene = test::write_two_quads(dir), exr = dir.file("o.exr");
    const test::CliResult r = test::run_penumbra(render_args(scene, exr, {}));
    ASSERT_EQ(r.status, 0) << r.output;
    const test::Pixels p = test::read_pixels(exr);
    EXPECT_EQ(at(p, "A", 0, 0), 1.0f);
    EXPECT_EQ(at(p, "R", 0, 0), 1.0f);  // the environment seen directly
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(exr);
    EXPECT_EQ(in->spec().get_string_attribute("penumbra:transparent_background"), "0");
    std::unique_ptr<OIIO::ImageInput> png = OIIO::ImageInput::open(dir.file("o.png"));
    ASSERT_TRUE(png);
    EXPECT_EQ(png->spec().nchannels, 3);
}

TEST(TransparentCli, DenoisingKeepsTheFilmsAlphaAndAnEmptyBackground) {
    const test::ScratchDir dir;
    const std::string scene = test::write_two_quads(dir);
    // The error AOV splits the samples as the denoiser does: the same film, not denoised.
    const test::CliResult d = test::run_penumbra(render_args(
        scene, dir.file("d.exr"), {"--transparent-background", "--denoise", "--no-preview"}));
    const test::CliResult e = test::run_penumbra(render_args(
        scene, dir.file("e.exr"), {"--transparent-background", "--aov", "error", "--no-preview"}));
    ASSERT_EQ(d.status, 0) << d.output;
    ASSERT_EQ(e.status, 0) << e.output;
    const test::Pixels dp = test::read_pixels(dir.file("d.exr")),
                       ep = test::read_pixels(dir.file("e.exr"));
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            EXPECT_EQ(at(dp, "A", x, y), at(ep, "A", x, y)) << x << "," << y;
            EXPECT_EQ(at(dp, "Noisy.R", x, y), at(ep, "R", x, y)) << x << "," << y;
            if (at(dp, "A", x, y) == 0)
                for (const char* c : {"R", "G", "B"}) EXPECT_EQ(at(dp, c, x, y), 0.0f);
        }
}

TEST(TransparentCli, FarmBandsMergeToTheImagesOfOneMachine) {
    const test::ScratchDir dir;
    const std::string scene = test::write_two_quads(dir);
    auto job = [&](const std::string& name, const std::string& out_dir) {
        return dir.write(
            name,
            R"({
  "defaults": {"width": 16, "height": 16, "spp": 4, "env_color": [1, 1, 1], "filter": "box",
               "transparent_background": true, "out_dir": ")" +
                out_dir + R"("},
  "jobs": [
    {"scene": ")" +
                scene +
                R"(", "bands": 3, "name": "ids.exr", "aov": "object_id,material_id,cryptomatte"},
    {"scene": ")" +
                scene + R"(", "bands": 2, "name": "denoised.exr", "denoise": true}
  ]
})");
    };
    const std::string ref_job = job("ref.json", "ref"), farm_job = job("farm.json", "farm");
    const test::CliResult ref = test::run_penumbra({"render", "--job", ref_job, "-q"});
    ASSERT_EQ(ref.status, 0) << ref.output;
    for (int i = 0; i < 5; ++i) {
        const test::CliResult t =
            test::run_penumbra({"farm", "task", farm_job, "--index", std::to_string(i)});
        EXPECT_EQ(t.status, 0) << i << ": " << t.output;
    }
    const test::CliResult m = test::run_penumbra({"farm", "merge", farm_job});
    ASSERT_EQ(m.status, 0) << m.output;
    for (const char* name : {"ids.exr", "ids.png", "denoised.exr", "denoised.png"})
        EXPECT_TRUE(test::same_pixels(dir.file(std::string("ref/") + name),
                                      dir.file(std::string("farm/") + name)))
            << name;
    // The merged header keeps the Cryptomatte entries.
    auto header = [&](const std::string& path, const std::string& key) {
        std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
        return in ? std::string(in->spec().get_string_attribute(key)) : std::string("<no file>");
    };
    for (const char* layer : {"CryptoObject", "CryptoMaterial"})
        for (const char* entry : {"name", "hash", "conversion", "manifest"}) {
            const std::string key = cryptomatte_key(layer, entry);
            const std::string ref = header(dir.file("ref/ids.exr"), key);
            EXPECT_FALSE(ref.empty()) << key;
            EXPECT_EQ(header(dir.file("farm/ids.exr"), key), ref) << key;
        }
}

}  // namespace
}  // namespace penumbra
