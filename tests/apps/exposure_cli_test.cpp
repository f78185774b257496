// No silent black or blown-out image, end to end: --default-light auto looks at the view
// (a file whose lights leave it dark gets the default lights, one that lights it keeps its
// own), a nearly black or mostly clipped render ends with a warning naming the options
// that change it (recorded as penumbra:image_warning and flagged in a batch's table), and
// --no-file-lights / "no_file_lights" leave an environment as the only light.
//
// The scene: a 4 m white (albedo 0.8) square facing a camera 3 m away (yfov 0.8, so the
// square fills the view), lit by a point light 2 m in front of it. A light of I candela
// is I / 683 W/sr; the square's radiance is 0.8 / pi x E with E = I / 683 x cos / d^2,
// from 0.8 / pi x I / 683 / 4 = 9.3e-5 I at the centre to 1.9e-5 I at the view's corners
// (d^2 = 8.5 m^2, cos 0.69). So 2000 cd lights every pixel (0.04 to 0.19, over the
// 0.01 a lit pixel needs) and 2 cd none (under 2e-4); at +5 EV (x32) the 2000 cd view
// clips everywhere (over 1.2).
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <regex>
#include <string>
#include <vector>

#include "support/cli_process.h"
#include "support/exr_pixels.h"
#include "support/gltf_builder.h"

namespace penumbra {
namespace {

using Args = std::vector<std::string>;

struct Lamp {
    double candela = 2000;
    bool light = true;      // the point light (KHR_lights_punctual)
    bool emitter = false;   // a 20 cm emissive square (radiance 2) on the wall
    std::string generator;  // asset.generator; empty: none
    // A 1 m emissive square (radiance 2) 0.5 m behind the camera: facing away from the
    // view (+Z), or towards the wall (-Z). 0: none.
    int behind = 0;
};

Lamp lamp(double candela, bool light = true, bool emitter = false, std::string generator = "",
          int behind = 0) {
    Lamp l;
    l.candela = candela;
    l.light = light;
    l.emitter = emitter;
    l.generator = std::move(generator);
    l.behind = behind;
    return l;
}

std::string lamp_scene(const test::ScratchDir& dir, const std::string& name, const Lamp& s) {
    test::GltfBuilder b;
    b.add(std::vector<float>{-2, -2, 0, 2, -2, 0, 2, 2, 0, -2, 2, 0}, test::kFloat, "VEC3");
    b.add(std::vector<float>{-0.1f, -0.1f, 0.01f, 0.1f, -0.1f, 0.01f, 0.1f, 0.1f, 0.01f, -0.1f,
                             0.1f, 0.01f},
          test::kFloat, "VEC3");
    b.add(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, test::kUShort, "SCALAR");
    b.add(std::vector<float>{-0.5f, -0.5f, 3.5f, 0.5f, -0.5f, 3.5f, 0.5f, 0.5f, 3.5f, -0.5f, 0.5f,
                             3.5f},
          test::kFloat, "VEC3");
    b.add(std::vector<uint16_t>{0, 2, 1, 0, 3, 2}, test::kUShort, "SCALAR");
    std::string nodes = R"({"mesh": 0}, {"camera": 0, "translation": [0, 0, 3]})";
    std::string roots = "0, 1";
    if (s.light) {
        nodes +=
            R"(, {"translation": [0, 0, 2], "extensions": {"KHR_lights_punctual": {"light": 0}}})";
        roots += ", 2";
    }
    int next = s.light ? 3 : 2;
    if (s.emitter) {
        nodes += R"(, {"mesh": 1})";
        roots += ", " + std::to_string(next++);
    }
    if (s.behind) {
        nodes += s.behind > 0 ? R"(, {"mesh": 2})" : R"(, {"mesh": 3})";
        roots += ", " + std::to_string(next++);
    }
    const std::string members = R"(
      "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1],
                                              "metallicFactor": 1e-9, "roughnessFactor": 1}},
                    {"pbrMetallicRoughness": {"baseColorFactor": [0, 0, 0, 1]},
                     "emissiveFactor": [1, 1, 1],
                     "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 2}}}],
      "extensionsUsed": ["KHR_lights_punctual", "KHR_materials_emissive_strength"],
      "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "intensity": )" +
                                std::to_string(s.candela) + R"(}]}},
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 2, "material": 0}]},
                 {"primitives": [{"attributes": {"POSITION": 1}, "indices": 2, "material": 1}]},
                 {"primitives": [{"attributes": {"POSITION": 3}, "indices": 2, "material": 1}]},
                 {"primitives": [{"attributes": {"POSITION": 3}, "indices": 4, "material": 1}]}],
      "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}],
      "nodes": [)" + nodes + R"(],
      "scenes": [{"nodes": [)" + roots +
                                R"(]}], "scene": 0)";
    std::string json = b.json(members, test::BufferStorage::DataUri);
    if (!s.generator.empty()) {
        const std::string asset = R"("asset":{"version":"2.0")";
        json.replace(json.find(asset), asset.size(),
                     asset + ",\"generator\":\"" + s.generator + "\"");
    }
    return dir.write(name, json);
}

test::CliResult render(const std::string& scene, const std::string& out, const Args& more) {
    Args args = {"render", scene, "-o", out, "--spp", "4", "--width", "32", "--no-preview"};
    args.insert(args.end(), more.begin(), more.end());
    return test::run_penumbra(args);
}

std::string attribute(const std::string& exr, const std::string& name) {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(exr);
    if (!in) return "<cannot open " + exr + ">";
    return in->spec().get_string_attribute(name, "<none>");
}

bool has(const test::CliResult& r, const std::string& text) {
    return r.output.find(text) != std::string::npos;
}

bool warned(const test::CliResult& r) {
    return has(r, "image nearly black") || has(r, "image mostly clipped");
}

TEST(ExposureCli, AutoAddsTheDefaultLightsOnlyWhereTheFileLightsLeaveTheViewDark) {
    const test::ScratchDir dir;
    const std::string dim = lamp_scene(dir, "dim.gltf", lamp(2));
    const test::CliResult a = render(dim, dir.file("dim.exr"), {});
    ASSERT_EQ(a.status, 0) << a.output;
    EXPECT_TRUE(has(a, "the file's lights leave the view dark (0% of a preview's pixels"))
        << a.output;
    EXPECT_TRUE(has(a, "--default-light off renders the file's lights alone")) << a.output;
    EXPECT_EQ(attribute(dir.file("dim.exr"), "penumbra:default_lights_added"), "1");
    // Lit by the defaults, the image is fine: no warning about it.
    EXPECT_FALSE(has(a, "image nearly black")) << a.output;
    EXPECT_EQ(attribute(dir.file("dim.exr"), "penumbra:image_warning"), "<none>");
    // The preview leaves no trace in the image: it is what --default-light on renders.
    ASSERT_EQ(render(dim, dir.file("dim_on.exr"), {"--default-light", "on"}).status, 0);
    EXPECT_TRUE(test::same_pixels(dir.file("dim.exr"), dir.file("dim_on.exr")));

    const std::string lit = lamp_scene(dir, "lit.gltf", lamp(2000));
    const test::CliResult b = render(lit, dir.file("lit.exr"), {});
    ASSERT_EQ(b.status, 0) << b.output;
    EXPECT_FALSE(has(b, "leave the view dark")) << b.output;
    EXPECT_EQ(attribute(dir.file("lit.exr"), "penumbra:default_lights_added"), "0");
    ASSERT_EQ(render(lit, dir.file("lit_off.exr"), {"--default-light", "off"}).status, 0);
    EXPECT_TRUE(test::same_pixels(dir.file("lit.exr"), dir.file("lit_off.exr")));
}

// Emitters that pass the rule on power and radiance (6.3 W, 5.8% of the defaults' 108 W
// on the 3.3 m bounding sphere; radiance 2) but face away from everything the camera
// sees: the view decides. Turned towards the wall, the same square lights it (0.015 at
// the corners to 0.042 at the centre).
TEST(ExposureCli, AutoWeighsEmittersByWhatTheCameraSees) {
    const test::ScratchDir dir;
    const std::string away = lamp_scene(dir, "away.gltf", lamp(0, false, false, "", +1));
    const test::CliResult a = render(away, dir.file("away.exr"), {});
    ASSERT_EQ(a.status, 0) << a.output;
    EXPECT_TRUE(has(a, "lighting: the file's emitters")) << a.output;
    EXPECT_TRUE(has(a, "the file's lights leave the view dark")) << a.output;
    EXPECT_EQ(attribute(dir.file("away.exr"), "penumbra:default_lights_added"), "1");

    const std::string towards = lamp_scene(dir, "towards.gltf", lamp(0, false, false, "", -1));
    const test::CliResult t = render(towards, dir.file("towards.exr"), {});
    ASSERT_EQ(t.status, 0) << t.output;
    EXPECT_TRUE(has(t, "the view is lit by the file's lights")) << t.output;
    EXPECT_EQ(attribute(dir.file("towards.exr"), "penumbra:default_lights_added"), "0");
    EXPECT_FALSE(warned(t)) << t.output;
}

TEST(ExposureCli, ANearlyBlackImageEndsWithAWarningNamingTheOptions) {
    const test::ScratchDir dir;
    const std::string dim = lamp_scene(dir, "dim.gltf", lamp(2));
    const test::CliResult r = render(dim, dir.file("dim.exr"), {"--default-light", "off"});
    ASSERT_EQ(r.status, 0) << r.output;
    const size_t at = r.output.rfind("image nearly black: 0% of its pixels");
    ASSERT_NE(at, std::string::npos) << r.output;
    // After the image's report, and naming the options that change it.
    EXPECT_GT(at, r.output.find("rays/s")) << r.output;
    EXPECT_TRUE(has(r, "--default-light auto or on adds a key and a fill light")) << r.output;
    EXPECT_TRUE(has(r, "--light-units radiometric reads them 683 times brighter")) << r.output;
    const std::string recorded = attribute(dir.file("dim.exr"), "penumbra:image_warning");
    EXPECT_EQ(recorded.rfind("image nearly black: ", 0), 0u) << recorded;

    const std::string lit = lamp_scene(dir, "lit.gltf", lamp(2000));
    const test::CliResult ok = render(lit, dir.file("lit.exr"), {"--default-light", "off"});
    ASSERT_EQ(ok.status, 0) << ok.output;
    EXPECT_FALSE(has(ok, "image nearly black")) << ok.output;
    EXPECT_EQ(attribute(dir.file("lit.exr"), "penumbra:image_warning"), "<none>");
}

// Khronos glTF Blender I/O 1.x wrote a lamp's watts as candela: a 10 W lamp read as
// 10 cd is 0.0015 W/sr (dark: under 1e-3 on the square), read as W/sr it lights it.
TEST(ExposureCli, BlenderOneLightsAreNamedAsWattsWrittenAsCandela) {
    const test::ScratchDir dir;
    const std::string old =
        lamp_scene(dir, "old.gltf", lamp(10, true, false, "Khronos glTF Blender I/O v1.6.16"));
    const test::CliResult a = render(old, dir.file("a.exr"), {});
    ASSERT_EQ(a.status, 0) << a.output;
    EXPECT_TRUE(has(a, "leave the view dark")) << a.output;
    EXPECT_TRUE(has(a,
                    "likely cause: the file's lights look like watts written as candela "
                    "('Khronos glTF Blender I/O v1.6.16' wrote a lamp's power as its "
                    "intensity; --light-units radiometric reads them as W/sr"))
        << a.output;
    const test::CliResult off = render(old, dir.file("off.exr"), {"--default-light", "off"});
    EXPECT_TRUE(has(off, "image nearly black")) << off.output;
    EXPECT_TRUE(has(off, "look like watts written as candela")) << off.output;
    EXPECT_NE(attribute(dir.file("off.exr"), "penumbra:image_warning").find("--exposure -3.7"),
              std::string::npos);
    // Read as W/sr, the lamp lights the view: no defaults, no warning.
    const test::CliResult w = render(old, dir.file("w.exr"), {"--light-units", "radiometric"});
    EXPECT_FALSE(has(w, "leave the view dark")) << w.output;
    EXPECT_FALSE(warned(w)) << w.output;
    // A later exporter writes candela: dark is then not blamed on units it got right.
    const std::string now =
        lamp_scene(dir, "now.gltf", lamp(10, true, false, "Khronos glTF Blender I/O v3.6.27"));
    const test::CliResult n = render(now, dir.file("n.exr"), {});
    EXPECT_TRUE(has(n, "leave the view dark")) << n.output;
    EXPECT_FALSE(has(n, "watts written as candela")) << n.output;
}

TEST(ExposureCli, AMostlyClippedImageNamesExposureAndUnits) {
    const test::ScratchDir dir;
    const std::string lit = lamp_scene(dir, "lit.gltf", lamp(2000));
    const test::CliResult r = render(lit, dir.file("hot.exr"), {"--exposure", "5"});
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(has(r, "image mostly clipped: 100% of its pixels exceed display white"))
        << r.output;
    EXPECT_EQ(attribute(dir.file("hot.exr"), "penumbra:image_warning").rfind("image mostly", 0),
              0u);
    // The suggested exposure brings the median to 18% grey: rendered with it, no warning.
    std::smatch m;
    ASSERT_TRUE(
        std::regex_search(r.output, m, std::regex("--exposure ([-+0-9.]+) brings the median")))
        << r.output;
    const double ev = std::stod(m[1].str());
    EXPECT_LT(ev, 5.0);  // an exposure to use instead of +5, not a change
    const test::CliResult fixed = render(lit, dir.file("fixed.exr"), {"--exposure", m[1].str()});
    EXPECT_FALSE(warned(fixed)) << fixed.output;

    // Candela read as W/sr: 683 times too bright, and the units are named.
    const test::CliResult u = render(lit, dir.file("units.exr"), {"--light-units", "radiometric"});
    EXPECT_TRUE(has(u, "image mostly clipped")) << u.output;
    EXPECT_TRUE(has(u,
                    "--light-units photometric, the spec's candela and lux, reads them 683 "
                    "times dimmer"))
        << u.output;
}

TEST(ExposureCli, ABatchTableFlagsNearlyBlackImages) {
    const test::ScratchDir dir;
    const std::string dim = lamp_scene(dir, "dim.gltf", lamp(2));
    const std::string lit = lamp_scene(dir, "lit.gltf", lamp(2000));
    const test::CliResult r =
        test::run_penumbra({"render", dim, lit, "--out-dir", dir.file("out"), "--spp", "1",
                            "--width", "16", "--no-preview", "--default-light", "off"});
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(std::regex_search(r.output, std::regex("dim\\.gltf .* BLACK .*dim\\.exr")))
        << r.output;
    EXPECT_FALSE(std::regex_search(r.output, std::regex("lit\\.gltf[^\n]*BLACK"))) << r.output;
    EXPECT_TRUE(has(r,
                    "2 images: 2 ok, 0 partial, 0 failed, 0 skipped; 1 nearly black, 0 "
                    "mostly clipped"))
        << r.output;
    // Without flagged images the table has no image column and no count.
    const test::CliResult ok = test::run_penumbra(
        {"render", lit, "--out-dir", dir.file("out2"), "--name", "{scene}_{index}.exr", "--frames",
         "0-1", "--spp", "1", "--width", "16", "--no-preview"});
    ASSERT_EQ(ok.status, 0) << ok.output;
    EXPECT_TRUE(has(ok, "2 images: 2 ok, 0 partial, 0 failed, 0 skipped\n")) << ok.output;
    EXPECT_FALSE(has(ok, " image ")) << ok.output;
    EXPECT_FALSE(warned(ok)) << ok.output;
}

TEST(ExposureCli, NoFileLightsLeavesTheEnvironmentAndTheEmittersAsTheOnlyLight) {
    const test::ScratchDir dir;
    const std::string with = lamp_scene(dir, "with.gltf", lamp(2000, true, true));
    const std::string without = lamp_scene(dir, "without.gltf", lamp(2000, false, true));
    const Args env = {"--env-color", "0.5", "0.5", "0.5"};
    Args no = env;
    no.push_back("--no-file-lights");
    const test::CliResult r = render(with, dir.file("no.exr"), no);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(has(r, "1 punctual light(s) of the file left out (--no-file-lights)")) << r.output;
    EXPECT_EQ(attribute(dir.file("no.exr"), "penumbra:no_file_lights"), "1");
    // Bit for bit the file without its light: the emitter and the environment remain.
    ASSERT_EQ(render(without, dir.file("without.exr"), env).status, 0);
    EXPECT_TRUE(test::same_pixels(dir.file("no.exr"), dir.file("without.exr")));
    ASSERT_EQ(render(with, dir.file("with.exr"), env).status, 0);
    EXPECT_EQ(attribute(dir.file("with.exr"), "penumbra:no_file_lights"), "0");
    EXPECT_FALSE(test::same_pixels(dir.file("no.exr"), dir.file("with.exr")));

    const std::string job =
        dir.write("job.json", R"({"jobs": [{"scene": ")" + with + R"(", "no_file_lights": true,
                                  "output": "j.exr", "spp": 4, "width": 32}]})");
    Args args = {"render", "--job", job, "--no-preview", "-q"};
    args.insert(args.end(), env.begin(), env.end());
    const test::CliResult j = test::run_penumbra(args);
    ASSERT_EQ(j.status, 0) << j.output;
    EXPECT_EQ(attribute(dir.file("j.exr"), "penumbra:no_file_lights"), "1");
    EXPECT_TRUE(test::same_pixels(dir.file("j.exr"), dir.file("without.exr")));
}

}  // namespace
}  // namespace penumbra
