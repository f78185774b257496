// The render command's light options end to end: --light-units (photometric by default,
// radiometric 683 times brighter), --exposure (the EXR scaled by exactly 2^EV), the
// --default-light modes on a helmet-like scene and the Cornell box, the notice that says
// which lighting was used, the EXR header fields and the job file keys.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <numeric>

#include "support/cli_process.h"
#include "support/gltf_builder.h"
#include "support/paths.h"

namespace penumbra {
namespace {

using Args = std::vector<std::string>;

struct Exr {
    OIIO::ImageSpec spec;
    std::vector<float> pixels;  // all channels
    // Mean of R, G, B over the image.
    double mean_rgb() const {
        double sum = 0;
        for (size_t i = 0; i < pixels.size(); ++i)
            if (int(i % size_t(spec.nchannels)) < 3) sum += pixels[i];
        return sum / (double(pixels.size()) / spec.nchannels * 3);
    }
};

Exr read_exr(const std::string& path) {
    Exr e;
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    EXPECT_TRUE(in) << OIIO::geterror();
    if (!in) return e;
    e.spec = in->spec();
    e.pixels.resize(size_t(e.spec.width) * e.spec.height * e.spec.nchannels);
    EXPECT_TRUE(in->read_image(0, 0, 0, e.spec.nchannels, OIIO::TypeDesc::FLOAT, e.pixels.data()));
    return e;
}

// A small render of scene to out (with its PNG preview when `preview`).
test::CliResult render(const std::string& scene, const std::string& out, const Args& more,
                       bool preview = false) {
    Args args = {"render", scene, "-o", out, "--spp", "2", "--width", "32"};
    if (!preview) args.push_back("--no-preview");
    args.insert(args.end(), more.begin(), more.end());
    return test::run_penumbra(args);
}

// A 2 m diffuse square facing +Z with a 2 cm emissive patch (radiance 5) just in front of
// it: DamagedHelmet's case, a big asset whose only emission is a small logo.
std::string helmet_like(const test::ScratchDir& dir) {
    test::GltfBuilder b;
    b.add(std::vector<float>{-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}, test::kFloat, "VEC3",
          "\"min\":[-1,-1,0],\"max\":[1,1,0]");
    b.add(std::vector<float>{-0.01f, -0.01f, 0.01f, 0.01f, -0.01f, 0.01f, 0.01f, 0.01f, 0.01f,
                             -0.01f, 0.01f, 0.01f},
          test::kFloat, "VEC3", "\"min\":[-0.01,-0.01,0.01],\"max\":[0.01,0.01,0.01]");
    b.add(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, test::kUShort, "SCALAR");
    const std::string members = R"(
      "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1],
                                              "metallicFactor": 0}},
                    {"pbrMetallicRoughness": {"baseColorFactor": [0, 0, 0, 1]},
                     "emissiveFactor": [1, 1, 1],
                     "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 5}}}],
      "extensionsUsed": ["KHR_materials_emissive_strength"],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 2, "material": 0}]},
                 {"primitives": [{"attributes": {"POSITION": 1}, "indices": 2, "material": 1}]}],
      "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}],
      "nodes": [{"mesh": 0}, {"mesh": 1}, {"camera": 0, "translation": [0, 0, 3]}],
      "scenes": [{"nodes": [0, 1, 2]}], "scene": 0)";
    return b.write(dir, "helmet.gltf", members, test::BufferStorage::DataUri);
}

TEST(LightCli, ExposureScalesTheExrByExactlyTwoToTheEv) {
    const test::ScratchDir dir;
    const std::string scene = test::source_path("scenes/cornell-box.gltf");
    ASSERT_EQ(render(scene, dir.file("a.exr"), {"--aov", "variance,albedo"}, true).status, 0);
    const test::CliResult r =
        render(scene, dir.file("b.exr"), {"--aov", "variance,albedo", "--exposure", "1.5"}, true);
    ASSERT_EQ(r.status, 0) << r.output;
    const Exr a = read_exr(dir.file("a.exr")), b = read_exr(dir.file("b.exr"));
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    ASSERT_EQ(a.spec.channelnames, b.spec.channelnames);
    const float scale = std::exp2(1.5f);
    // Colour times 2^EV, variance times 4^EV, alpha and albedo unchanged.
    std::vector<float> factor;
    for (const std::string& name : a.spec.channelnames)
        factor.push_back(name == "R" || name == "G" || name == "B" ? scale
                         : name.rfind("Variance.", 0) == 0         ? scale * scale
                                                                   : 1.0f);
    ASSERT_EQ(factor.size(), 10u);  // RGBA, Albedo.RGB, Variance.RGB
    size_t lit = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        const float f = factor[i % factor.size()];
        // One or two float multiplications: within an ULP of the exact product.
        EXPECT_NEAR(b.pixels[i], f * a.pixels[i], 1.2e-7f * std::abs(b.pixels[i])) << i;
        lit += f == scale && a.pixels[i] > 0;
    }
    EXPECT_GT(lit, a.pixels.size() / 10 * 3 / 2);  // most colour values are nonzero
    EXPECT_FLOAT_EQ(a.spec.get_float_attribute("penumbra:exposure", -1), 0.0f);
    EXPECT_FLOAT_EQ(b.spec.get_float_attribute("penumbra:exposure", -1), 1.5f);
    // The preview is exposed too: 2.8 times the light through the display curve.
    const Exr pa = read_exr(dir.file("a.png")), pb = read_exr(dir.file("b.png"));
    ASSERT_EQ(pa.pixels.size(), pb.pixels.size());
    EXPECT_GT(pb.mean_rgb(), 1.3 * pa.mean_rgb());
}

TEST(LightCli, RadiometricUnitsRead683TimesBrighter) {
    const test::ScratchDir dir;
    const std::string scene = test::source_path("scenes/cornell-box-point.gltf");
    ASSERT_EQ(render(scene, dir.file("p.exr"), {}).status, 0);
    ASSERT_EQ(render(scene, dir.file("r.exr"), {"--light-units", "radiometric"}).status, 0);
    const Exr p = read_exr(dir.file("p.exr")), r = read_exr(dir.file("r.exr"));
    EXPECT_EQ(p.spec.get_string_attribute("penumbra:light_units"), "photometric");
    EXPECT_EQ(r.spec.get_string_attribute("penumbra:light_units"), "radiometric");
    ASSERT_GT(p.mean_rgb(), 0.01);
    // Same samples, every radiance linear in the one light: the ratio is 683 up to float
    // rounding of the sums.
    EXPECT_NEAR(r.mean_rgb() / p.mean_rgb(), 683.0, 683.0 * 1e-5);
    const test::CliResult bad = render(scene, dir.file("x.exr"), {"--light-units", "lumens"});
    EXPECT_NE(bad.status, 0);
}

TEST(LightCli, AutoLightsAHelmetLikeSceneAndNotesWhy) {
    const test::ScratchDir dir;
    const std::string scene = helmet_like(dir);
    const test::CliResult a = render(scene, dir.file("auto.exr"), {});
    ASSERT_EQ(a.status, 0) << a.output;
    EXPECT_NE(a.output.find("lighting: emitters too small"), std::string::npos) << a.output;
    const test::CliResult off = render(scene, dir.file("off.exr"), {"--default-light", "off"});
    ASSERT_EQ(off.status, 0) << off.output;
    EXPECT_NE(off.output.find("lighting: the scene's own lights only"), std::string::npos)
        << off.output;
    ASSERT_EQ(render(scene, dir.file("no.exr"), {"--no-default-light"}).status, 0);
    ASSERT_EQ(render(scene, dir.file("on.exr"), {"--default-light", "on"}).status, 0);
    const Exr lit = read_exr(dir.file("auto.exr")), dark = read_exr(dir.file("off.exr")),
              no = read_exr(dir.file("no.exr")), on = read_exr(dir.file("on.exr"));
    EXPECT_EQ(lit.spec.get_string_attribute("penumbra:default_lights_added"), "1");
    EXPECT_EQ(dark.spec.get_string_attribute("penumbra:default_lights_added"), "0");
    EXPECT_EQ(dark.spec.get_string_attribute("penumbra:default_light"), "off");
    EXPECT_EQ(no.pixels, dark.pixels);  // --no-default-light is --default-light off
    EXPECT_EQ(on.pixels, lit.pixels);   // auto chose what on forces
    // The square fills most of the view: lit, it averages ~0.5; by its patch alone the
    // image is nearly black (the patch is a pixel or two; its light is a speck).
    std::printf("helmet-like: mean %.4f with the default lighting, %.6f without\n", lit.mean_rgb(),
                dark.mean_rgb());
    EXPECT_GT(lit.mean_rgb(), 0.2);
    EXPECT_LT(dark.mean_rgb(), 0.02 * lit.mean_rgb());
}

TEST(LightCli, AutoLeavesTheCornellBoxToItsPanel) {
    const test::ScratchDir dir;
    const std::string scene = test::source_path("scenes/cornell-box.gltf");
    const test::CliResult a = render(scene, dir.file("auto.exr"), {});
    ASSERT_EQ(a.status, 0) << a.output;
    EXPECT_NE(a.output.find("lighting: the file's emitters"), std::string::npos) << a.output;
    ASSERT_EQ(render(scene, dir.file("off.exr"), {"--default-light", "off"}).status, 0);
    ASSERT_EQ(render(scene, dir.file("on.exr"), {"--default-light", "on"}).status, 0);
    const Exr a_img = read_exr(dir.file("auto.exr")), off = read_exr(dir.file("off.exr")),
              on = read_exr(dir.file("on.exr"));
    EXPECT_EQ(a_img.spec.get_string_attribute("penumbra:default_lights_added"), "0");
    EXPECT_EQ(a_img.pixels, off.pixels);
    EXPECT_EQ(on.spec.get_string_attribute("penumbra:default_lights_added"), "1");
    EXPECT_GT(on.mean_rgb(), 1.2 * off.mean_rgb());
}

TEST(LightCli, JobFileKeysReachTheRender) {
    const test::ScratchDir dir;
    const std::string job = dir.write("job.json", R"({"defaults": {"exposure": -1},
        "jobs": [{"scene": ")" + test::source_path("scenes/cornell-box-point.gltf") +
                                                      R"(", "light_units": "radiometric",
                  "default_light": "on", "output": "j.exr"}]})");
    const test::CliResult r = test::run_penumbra(
        {"render", "--job", job, "--spp", "1", "--width", "16", "--no-preview", "-q"});
    ASSERT_EQ(r.status, 0) << r.output;
    const Exr e = read_exr(dir.file("j.exr"));
    EXPECT_EQ(e.spec.get_string_attribute("penumbra:light_units"), "radiometric");
    EXPECT_EQ(e.spec.get_string_attribute("penumbra:default_light"), "on");
    EXPECT_EQ(e.spec.get_string_attribute("penumbra:default_lights_added"), "1");
    EXPECT_FLOAT_EQ(e.spec.get_float_attribute("penumbra:exposure", 0), -1.0f);
}

// A 16 x 8 equirectangular sky (a bright top row over grey) written as EXR in dir.
std::string small_sky(const test::ScratchDir& dir) {
    const std::string path = dir.file("sky.exr");
    std::vector<float> rgb(16 * 8 * 3, 0.3f);
    for (int i = 0; i < 16 * 3; ++i) rgb[i] = 4.0f;
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
    EXPECT_TRUE(out);
    if (!out) return path;
    EXPECT_TRUE(out->open(path, OIIO::ImageSpec(16, 8, 3, OIIO::TypeDesc::FLOAT)));
    EXPECT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, rgb.data()));
    out->close();
    return path;
}

// --env-sampling: auto compensates under the path tracer's MIS and not under the basic
// integrator, the header says which, compensated without MIS pairs is refused before any
// output is written, and the job-file key reaches the render.
TEST(LightCli, EnvSamplingFollowsTheIntegratorAndIsRecorded) {
    const test::ScratchDir dir;
    const std::string scene = test::source_path("scenes/cornell-box-point.gltf");
    const std::string sky = small_sky(dir);
    auto sampling = [&](const std::string& name, const Args& more) {
        const test::CliResult r = render(scene, dir.file(name), more);
        EXPECT_EQ(r.status, 0) << r.output;
        return read_exr(dir.file(name)).spec.get_string_attribute("penumbra:env_sampling");
    };
    EXPECT_EQ(sampling("auto.exr", {"--env", sky}), "compensated");
    EXPECT_EQ(sampling("full.exr", {"--env", sky, "--env-sampling", "full"}), "full");
    EXPECT_EQ(sampling("basic.exr", {"--env", sky, "--integrator", "basic"}), "full");
    EXPECT_EQ(sampling("light.exr", {"--env", sky, "--strategy", "light"}), "full");
    EXPECT_EQ(sampling("none.exr", {"--default-light", "off"}), "none");

    const test::CliResult bad =
        render(scene, dir.file("bad.exr"),
               {"--env", sky, "--integrator", "basic", "--env-sampling", "compensated"});
    EXPECT_NE(bad.status, 0);
    EXPECT_NE(bad.output.find("--env-sampling compensated needs"), std::string::npos) << bad.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("bad.exr")));

    const std::string job =
        dir.write("job.json", R"({"jobs": [{"scene": ")" + scene +
                                  R"(", "env_sampling": "full", "output": "j.exr"}]})");
    const test::CliResult r = test::run_penumbra({"render", "--job", job, "--env", sky, "--spp",
                                                  "1", "--width", "16", "--no-preview", "-q"});
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(read_exr(dir.file("j.exr")).spec.get_string_attribute("penumbra:env_sampling"),
              "full");
}

}  // namespace
}  // namespace penumbra
