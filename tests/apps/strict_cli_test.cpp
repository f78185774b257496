// render --strict and --max-texture-pixels, and the job file's "strict" key: a scene
// whose texture is a corrupt PNG renders with one warning and its factor colour, and
// fails naming the image, without writing the output, when warnings are errors.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "io/image/image_reader.h"
#include "support/cli_process.h"
#include "support/gltf_builder.h"

namespace penumbra {
namespace {

using test::BufferStorage;
using test::GltfBuilder;
using test::ScratchDir;

std::vector<uint8_t> png_bytes(const ScratchDir& dir, int w, int h) {
    const std::string path = dir.file("w.png");
    auto out = OIIO::ImageOutput::create(path);
    EXPECT_TRUE(out && out->open(path, OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::UINT8)));
    std::vector<uint8_t> px(size_t(w * h * 3), 0);  // black: tells the texture from the factor
    out->write_image(OIIO::TypeDesc::UINT8, px.data());
    out->close();
    std::ifstream f(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

// A triangle facing +Z whose base colour is factor (0.2, 0.4, 0.6) times the image tex.png.
std::string write_scene(const ScratchDir& dir, const std::vector<uint8_t>& png) {
    std::ofstream(dir.file("tex.png"), std::ios::binary)
        .write(reinterpret_cast<const char*>(png.data()), std::streamsize(png.size()));
    GltfBuilder b;
    b.add(std::vector<float>{-1, -1, 0, 1, -1, 0, 0, 1, 0}, test::kFloat, "VEC3",
          R"("min": [-1, -1, 0], "max": [1, 1, 0])");
    b.add(std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1}, test::kFloat, "VEC3");
    b.add(std::vector<float>{0, 0, 1, 0, 0, 1}, test::kFloat, "VEC2");
    const std::string members = R"("images": [{"uri": "tex.png"}], "textures": [{"source": 0}],
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.4, 0.6, 1],
                       "baseColorTexture": {"index": 0}}}],)" +
                                test::one_mesh_scene(R"({"attributes": {"POSITION": 0,
                                   "NORMAL": 1, "TEXCOORD_0": 2}, "material": 0})");
    return b.write(dir, "scene.gltf", members, BufferStorage::DataUri);
}

std::vector<std::string> args(const std::string& scene, const std::string& out,
                              std::vector<std::string> extra = {}) {
    std::vector<std::string> a = {"render", scene,     "-o",          out,        "--integrator",
                                  "albedo", "--width", "9",           "--height", "9",
                                  "--spp",  "1",       "--no-preview"};
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
}

float centre_red(const std::string& exr) {
    const Image img = read_image(exr, ImageEncoding::Linear);
    return img.at(img.width / 2, img.height / 2)[0];
}

TEST(StrictCli, CorruptTextureWarnsOrFailsWithStrict) {
    ScratchDir dir;
    std::vector<uint8_t> png = png_bytes(dir, 16, 16);
    png.resize(png.size() / 2);  // cut off inside the image data
    const std::string scene = write_scene(dir, png);
    const std::string warning = scene + ": images[0] ('tex.png'): cannot decode image: ";

    const test::CliResult lenient = test::run_penumbra(args(scene, dir.file("a.exr")));
    EXPECT_EQ(lenient.status, 0) << lenient.output;
    EXPECT_NE(lenient.output.find("warning: " + warning), std::string::npos) << lenient.output;
    EXPECT_NEAR(centre_red(dir.file("a.exr")), 0.2f, 1e-4f);  // the factor alone

    const test::CliResult strict = test::run_penumbra(args(scene, dir.file("b.exr"), {"--strict"}));
    EXPECT_EQ(strict.status, 1) << strict.output;
    EXPECT_NE(strict.output.find("error: " + warning), std::string::npos) << strict.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("b.exr")));

    const std::string job = dir.write("job.json", R"({"defaults": {"strict": true}, "jobs": [
            {"scene": "scene.gltf", "output": "c.exr"}]})");
    const test::CliResult from_job =
        test::run_penumbra({"render", "--job", job, "--integrator", "albedo", "--width", "9",
                            "--spp", "1", "--no-preview"});
    EXPECT_NE(from_job.status, 0) << from_job.output;
    EXPECT_NE(from_job.output.find(warning), std::string::npos) << from_job.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("c.exr")));
}

TEST(StrictCli, MaxTexturePixels) {
    ScratchDir dir;
    const std::string scene = write_scene(dir, png_bytes(dir, 4, 4));
    const test::CliResult fits =
        test::run_penumbra(args(scene, dir.file("a.exr"), {"--max-texture-pixels", "16"}));
    EXPECT_EQ(fits.status, 0) << fits.output;
    EXPECT_NEAR(centre_red(dir.file("a.exr")), 0.0f, 1e-4f);  // black texture times factor
    const test::CliResult refused =
        test::run_penumbra(args(scene, dir.file("b.exr"), {"--max-texture-pixels", "15"}));
    EXPECT_EQ(refused.status, 0) << refused.output;
    EXPECT_NE(refused.output.find("4x4 is more than the limit of 15 pixels"), std::string::npos)
        << refused.output;
    EXPECT_NEAR(centre_red(dir.file("b.exr")), 0.2f, 1e-4f);
}

}  // namespace
}  // namespace penumbra
