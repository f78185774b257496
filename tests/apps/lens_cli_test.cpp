// Depth of field from glTF and the command line, end to end: the lens scenes/dof.gltf
// describes (camera extras), EXT_cameras_sensor, and the --aperture-radius, --fstop,
// --focus-distance and --focus-on overrides, read back from the EXR header.
#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

#include "io/gltf/gltf_loader.h"
#include "support/cli_process.h"
#include "support/gltf_builder.h"
#include "support/paths.h"

namespace penumbra {
namespace {

using test::run_penumbra;

const std::string kDof = test::source_path("scenes/dof.gltf");

OIIO::ImageSpec header(const std::string& path) {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    EXPECT_TRUE(in) << OIIO::geterror();
    return in ? in->spec() : OIIO::ImageSpec();
}

// Renders dof.gltf small and fast with extra options into dir/name.
std::string render(const test::ScratchDir& dir, const std::string& name,
                   std::vector<std::string> extra) {
    std::vector<std::string> args = {"render", kDof, "-o", dir.file(name), "--width", "24",
                                     "--spp", "2", "--no-preview", "-q"};
    args.insert(args.end(), extra.begin(), extra.end());
    const test::CliResult r = run_penumbra(args);
    EXPECT_EQ(r.status, 0) << r.output;
    return dir.file(name);
}

bool same_pixels(const std::string& a, const std::string& b) {
    const OIIO::ImageBuf A(a), B(b);
    const auto cmp = OIIO::ImageBufAlgo::compare(A, B, 0, 0);
    return cmp.nfail == 0 && cmp.maxerror == 0;
}

// The focal length of a perspective camera of vertical field of view yfov on a sensor
// of the given height, and the aperture radius of f-number N: f / (2 N).
double aperture_from_fstop(double fstop, double yfov, double sensor_mm) {
    const double focal_mm = 0.5 * sensor_mm / std::tan(0.5 * yfov);
    return focal_mm / (2 * fstop) / 1000;  // metres
}

TEST(LensCli, TheFileDescribesTheLens) {
    const Scene scene = load_gltf(kDof);
    ASSERT_EQ(scene.cameras.size(), 1u);
    EXPECT_FLOAT_EQ(scene.cameras[0].aperture_radius, 0.05f);
    EXPECT_FLOAT_EQ(scene.cameras[0].focus_distance, 6.0f);
    EXPECT_EQ(scene.cameras[0].aperture_blades, 6);

    const test::ScratchDir dir;
    const OIIO::ImageSpec h = header(render(dir, "file.exr", {}));
    EXPECT_FLOAT_EQ(h.get_float_attribute("penumbra:aperture_radius"), 0.05f);
    EXPECT_FLOAT_EQ(h.get_float_attribute("penumbra:focus_distance"), 6.0f);
    EXPECT_EQ(h.get_int_attribute("penumbra:aperture_blades"), 6);
}

TEST(LensCli, ExtCamerasSensorGivesTheApertureFromTheFStop) {
    // dof.gltf with its camera extras replaced by the extension's sensor, f-stop and focus.
    std::ifstream in(kDof);
    std::stringstream text;
    text << in.rdbuf();
    const std::string edited = std::regex_replace(
        text.str(), std::regex(R"("extras": \{[^}]*\})"),
        R"("extensions": {"EXT_cameras_sensor": {"sensorHeight": 16.0, "fStop": 2.8, "focusDistance": 4.5}})");
    ASSERT_NE(edited, text.str());
    const test::ScratchDir dir;
    const std::string file = dir.write("sensor.gltf", edited);
    const Scene scene = load_gltf(file);
    const CameraDesc& c = scene.cameras.at(0);
    EXPECT_FLOAT_EQ(c.sensor_height_mm, 16.0f);
    EXPECT_FLOAT_EQ(c.focus_distance, 4.5f);
    EXPECT_NEAR(c.aperture_radius, aperture_from_fstop(2.8, c.yfov, 16.0), 1e-7);
}

TEST(LensCli, CommandLineOverridesTheFile) {
    const test::ScratchDir dir;
    const std::string lens = render(dir, "lens.exr", {});
    // A pinhole, whatever the file says: the focus distance then changes nothing.
    const std::string pinhole = render(dir, "pinhole.exr", {"--aperture-radius", "0"});
    const std::string pinhole_refocused =
        render(dir, "pinhole2.exr", {"--aperture-radius", "0", "--focus-distance", "2"});
    EXPECT_FLOAT_EQ(header(pinhole).get_float_attribute("penumbra:aperture_radius"), 0.0f);
    EXPECT_TRUE(same_pixels(pinhole, pinhole_refocused));
    EXPECT_FALSE(same_pixels(pinhole, lens));

    // --fstop: the aperture from the camera's focal length on a 24 mm sensor.
    const OIIO::ImageSpec f2 = header(render(dir, "f2.exr", {"--fstop", "2", "--focus-distance", "3"}));
    const double yfov = load_gltf(kDof).cameras.at(0).yfov;
    EXPECT_NEAR(f2.get_float_attribute("penumbra:aperture_radius"),
                aperture_from_fstop(2, yfov, 24), 1e-6);
    EXPECT_FLOAT_EQ(f2.get_float_attribute("penumbra:focus_distance"), 3.0f);

    // --focus-on the centre pixel: the ray meets the middle sphere (centre (0, 0.4, -5),
    // radius 0.4) at height 0.6, z = -5 + sqrt(0.4^2 - 0.2^2), from the camera at z = 1.
    const OIIO::ImageSpec on = header(render(dir, "on.exr", {"--focus-on", "12", "8"}));
    EXPECT_NEAR(on.get_float_attribute("penumbra:focus_distance"),
                1 - (-5 + std::sqrt(0.16 - 0.04)), 2e-3);

    // --fstop and --aperture-radius say the same thing twice.
    const test::CliResult both = run_penumbra({"render", kDof, "-o", dir.file("x.exr"), "--fstop",
                                               "2", "--aperture-radius", "0.1"});
    EXPECT_NE(both.status, 0);
    EXPECT_NE(both.output.find("excludes"), std::string::npos) << both.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("x.exr")));
}

}  // namespace
}  // namespace penumbra
