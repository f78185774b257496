// render --variant and the job file's "variant" key reach the loader: the albedo view of
// a triangle whose material each variant changes, and the error for an unknown name.
#include <gtest/gtest.h>

#include <string>

#include "io/image/image_reader.h"
#include "support/cli_process.h"
#include "support/gltf_builder.h"

namespace penumbra {
namespace {

using test::BufferStorage;
using test::GltfBuilder;
using test::ScratchDir;

// A triangle facing +Z around the origin: grey by default, red or blue by variant.
std::string write_scene(const ScratchDir& dir) {
    GltfBuilder b;
    b.add(std::vector<float>{-1, -1, 0, 1, -1, 0, 0, 1, 0}, test::kFloat, "VEC3",
          R"("min": [-1, -1, 0], "max": [1, 1, 0])");
    b.add(std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1}, test::kFloat, "VEC3");
    const std::string members = R"("extensionsUsed": ["KHR_materials_variants"],
        "extensions": {"KHR_materials_variants": {"variants": [{"name": "red"}, {"name": "blue"}]}},
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1]}},
                      {"pbrMetallicRoughness": {"baseColorFactor": [1, 0, 0, 1]}},
                      {"pbrMetallicRoughness": {"baseColorFactor": [0, 0, 1, 1]}}],)" +
                                test::one_mesh_scene(R"({"attributes": {"POSITION": 0, "NORMAL": 1},
        "material": 0, "extensions": {"KHR_materials_variants": {"mappings": [
            {"material": 1, "variants": [0]}, {"material": 2, "variants": [1]}]}}})");
    return b.write(dir, "variants.gltf", members, BufferStorage::DataUri);
}

// The albedo at the image centre (the triangle's bounding-box centre lies inside it).
Vec3 centre(const std::string& exr) {
    const Image img = read_image(exr, ImageEncoding::Linear);
    const float* p = img.at(img.width / 2, img.height / 2);
    return {p[0], p[1], p[2]};
}

TEST(VariantCli, VariantOptionAndJobKeyChooseTheMaterials) {
    ScratchDir dir;
    const std::string scene = write_scene(dir);
    const std::vector<std::string> common = {
        "--integrator", "albedo", "--width", "9", "--height", "9", "--spp", "1", "--no-preview"};
    auto render = [&](const std::vector<std::string>& extra, const std::string& out) {
        std::vector<std::string> args = {"render", scene, "-o", dir.file(out)};
        args.insert(args.end(), common.begin(), common.end());
        args.insert(args.end(), extra.begin(), extra.end());
        const test::CliResult r = test::run_penumbra(args);
        EXPECT_EQ(r.status, 0) << r.output;
        return centre(dir.file(out));
    };
    const Vec3 grey = render({}, "default.exr"), red = render({"--variant", "red"}, "red.exr"),
               blue = render({"--variant", "blue"}, "blue.exr");
    EXPECT_NEAR(grey.x, 0.5f, 1e-4f);
    EXPECT_NEAR(grey.z, 0.5f, 1e-4f);
    EXPECT_NEAR(red.x, 1.0f, 1e-4f);
    EXPECT_NEAR(red.z, 0.0f, 1e-4f);
    EXPECT_NEAR(blue.x, 0.0f, 1e-4f);
    EXPECT_NEAR(blue.z, 1.0f, 1e-4f);

    const std::string job = dir.write("job.json", R"({"defaults": {"variant": "red"}, "jobs": [
            {"scene": "variants.gltf", "output": "job-red.exr"},
            {"scene": "variants.gltf", "variant": "blue", "output": "job-blue.exr"}]})");
    std::vector<std::string> args = {"render", "--job", job};
    args.insert(args.end(), common.begin(), common.end());
    const test::CliResult r = test::run_penumbra(args);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NEAR(centre(dir.file("job-red.exr")).x, 1.0f, 1e-4f);
    EXPECT_NEAR(centre(dir.file("job-blue.exr")).z, 1.0f, 1e-4f);

    const test::CliResult bad =
        test::run_penumbra({"render", scene, "--variant", "green", "-o", dir.file("x.exr")});
    EXPECT_EQ(bad.status, 1);
    EXPECT_NE(bad.output.find("variants.gltf: extensions.KHR_materials_variants: no material "
                              "variant 'green' (the file has 'red', 'blue')"),
              std::string::npos)
        << bad.output;
}

}  // namespace
}  // namespace penumbra
