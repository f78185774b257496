// Colour management: the sRGB curve, the built-in OCIO config (spaces, roles, views),
// working-space matrices, chromaticities, previews, errors, and Blender's config.
#include "io/color/color.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "core/error.h"
#include "io/color/color_config.h"

namespace penumbra {
namespace {

// IEC 61966-2-1, written out here as the oracle the OCIO-backed curve must match.
double iec_srgb_to_linear(double v) {
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

double iec_linear_to_srgb(double v) {
    return v <= 0.0031308 ? v * 12.92 : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
}

ColorPipeline pipeline(const std::string& working, const std::string& output = "",
                       const std::string& view = "") {
    ColorSettings s;
    s.config = "builtin";
    s.working_space = working;
    s.output_space = output;
    s.view = view;
    return ColorPipeline(s);
}

void expect_chromaticities(const Chromaticities& c, const Chromaticities& want, float tol) {
    EXPECT_NEAR(c.red[0], want.red[0], tol);
    EXPECT_NEAR(c.red[1], want.red[1], tol);
    EXPECT_NEAR(c.green[0], want.green[0], tol);
    EXPECT_NEAR(c.green[1], want.green[1], tol);
    EXPECT_NEAR(c.blue[0], want.blue[0], tol);
    EXPECT_NEAR(c.blue[1], want.blue[1], tol);
    EXPECT_NEAR(c.white[0], want.white[0], tol);
    EXPECT_NEAR(c.white[1], want.white[1], tol);
}

TEST(Color, SrgbHalfDecodesTo0214) {
    EXPECT_NEAR(srgb_to_linear(0.5f), 0.214041f, 1e-6f);
    // OCIO's curve makes the toe meet the power segment with a continuous slope
    // (12.923 instead of the standard's rounded 12.92): 2.5e-4 relative below 0.04045,
    // under 1e-6 absolute everywhere, a hundredth of an 8-bit step.
    for (float v = 0; v <= 1.0f; v += 1.0f / 256)
        EXPECT_NEAR(srgb_to_linear(v), iec_srgb_to_linear(v), 1e-6) << v;
    for (int code = 0; code < 256; ++code)
        EXPECT_EQ(std::lround(linear_to_srgb(srgb_to_linear(code / 255.0f)) * 255), code);
    // A texture: colour channels decoded, alpha left linear.
    Image img(1, 1, 4);
    img.pixels = {0.5f, 0.5f, 0.5f, 0.5f};
    decode_srgb(img);
    EXPECT_NEAR(img.pixels[0], 0.214041f, 1e-6f);
    EXPECT_NEAR(img.pixels[2], 0.214041f, 1e-6f);
    EXPECT_EQ(img.pixels[3], 0.5f);
    Image gray_alpha(1, 1, 2);
    gray_alpha.pixels = {0.5f, 0.5f};
    decode_srgb(gray_alpha);
    EXPECT_NEAR(gray_alpha.pixels[0], 0.214041f, 1e-6f);
    EXPECT_EQ(gray_alpha.pixels[1], 0.5f);
}

TEST(Color, BuiltinConfigHasTheSpacesRolesAndViews) {
    const OCIO::ConstConfigRcPtr c = builtin_config();
    for (const char* s : {"Linear Rec.709 (sRGB)", "ACEScg", "ACES2065-1", "sRGB", "Raw"})
        EXPECT_TRUE(c->getColorSpace(s)) << s;
    for (const char* role :
         {OCIO::ROLE_SCENE_LINEAR, OCIO::ROLE_RENDERING, OCIO::ROLE_DATA, OCIO::ROLE_COLOR_PICKING,
          OCIO::ROLE_INTERCHANGE_SCENE, OCIO::ROLE_INTERCHANGE_DISPLAY, OCIO::ROLE_COMPOSITING_LOG})
        EXPECT_TRUE(c->hasRole(role)) << role;
    EXPECT_STREQ(c->getColorSpace(OCIO::ROLE_SCENE_LINEAR)->getName(), "Linear Rec.709 (sRGB)");
    EXPECT_TRUE(c->getColorSpace(OCIO::ROLE_DATA)->isData());
    EXPECT_STREQ(c->getDefaultDisplay(), "sRGB");
    EXPECT_STREQ(c->getDefaultView("sRGB"), "Standard");
    bool aces_view = false;
    for (int i = 0; i < c->getNumViews("sRGB"); ++i)
        aces_view |= std::string(c->getView("sRGB", i)) == "ACES 1.0 - SDR Video";
    EXPECT_TRUE(aces_view);
    EXPECT_NO_THROW(c->validate());
}

TEST(Color, DefaultsAreLinearRec709AndSrgbStandard) {
    const ColorPipeline& p = ColorPipeline::builtin();
    EXPECT_EQ(p.working_space(), "Linear Rec.709 (sRGB)");
    EXPECT_EQ(p.output_space(), p.working_space());
    EXPECT_EQ(p.display(), "sRGB");
    EXPECT_EQ(p.view(), "Standard");
    EXPECT_TRUE(p.working_is_rec709());
    EXPECT_TRUE(p.rec709_to_working().is_identity());
    ASSERT_TRUE(p.output_chromaticities());
    // Rec.709 primaries, D65 white (ITU-R BT.709-6).
    expect_chromaticities(*p.output_chromaticities(),
                          {{0.64f, 0.33f}, {0.30f, 0.60f}, {0.15f, 0.06f}, {0.3127f, 0.3290f}},
                          1e-6f);
}

TEST(Color, AcescgRoundTripIsIdentity) {
    const ColorPipeline& p = ColorPipeline::builtin();
    std::vector<float> rgb, original;
    for (int i = 0; i < 200; ++i)
        for (int c = 0; c < 3; ++c) rgb.push_back(std::fmod(0.37f * i + 0.61f * c, 4.0f) - 0.5f);
    original = rgb;
    p.convert(rgb.data(), rgb.size() / 3, "Linear Rec.709 (sRGB)", "ACEScg");
    EXPECT_GT(std::abs(rgb[3] - original[3]), 1e-2f);  // it did convert
    p.convert(rgb.data(), rgb.size() / 3, "ACEScg", "Linear Rec.709 (sRGB)");
    for (size_t i = 0; i < rgb.size(); ++i)
        EXPECT_NEAR(rgb[i], original[i], 1e-5f * std::max(1.0f, std::abs(original[i]))) << i;
}

TEST(Color, AcescgWorkingSpaceConvertsGltfColours) {
    const ColorPipeline p = pipeline("acescg");
    EXPECT_EQ(p.working_space(), "ACEScg");
    EXPECT_FALSE(p.working_is_rec709());
    // The published Rec.709 -> AP1 (Bradford D65 -> ACES white) matrix, first column:
    // pure Rec.709 red in ACEScg.
    const Vec3 red = p.rec709_to_working() * Vec3(1, 0, 0);
    EXPECT_NEAR(red.x, 0.613097f, 2e-5f);
    EXPECT_NEAR(red.y, 0.070194f, 2e-5f);
    EXPECT_NEAR(red.z, 0.020616f, 2e-5f);
    // White stays white; the matrix agrees with OCIO's own conversion.
    const Vec3 white = p.rec709_to_working() * Vec3(1, 1, 1);
    EXPECT_NEAR(white.x, 1, 1e-5f);
    EXPECT_NEAR(white.z, 1, 1e-5f);
    float c[3] = {0.2f, 0.7f, 0.4f};
    p.convert(c, 1, "Linear Rec.709 (sRGB)", "ACEScg");
    const Vec3 m = p.rec709_to_working() * Vec3(0.2f, 0.7f, 0.4f);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(m[i], c[i], 1e-5f);
}

TEST(Color, OutputChromaticitiesFollowTheOutputSpace) {
    const ColorPipeline cg = pipeline("", "ACEScg");
    ASSERT_TRUE(cg.output_chromaticities());
    // ACES AP1 (SMPTE ST 2065-1 / S-2014-004) with the ACES white.
    expect_chromaticities(
        *cg.output_chromaticities(),
        {{0.713f, 0.293f}, {0.165f, 0.830f}, {0.128f, 0.044f}, {0.32168f, 0.33767f}}, 1e-6f);
    const ColorPipeline ap0 = pipeline("acescg", "ACES2065-1");
    ASSERT_TRUE(ap0.output_chromaticities());
    expect_chromaticities(
        *ap0.output_chromaticities(),
        {{0.7347f, 0.2653f}, {0.0f, 1.0f}, {0.0001f, -0.0770f}, {0.32168f, 0.33767f}}, 1e-6f);
    // An encoded (non-linear) output has no chromaticities to claim.
    EXPECT_FALSE(pipeline("", "sRGB").output_chromaticities());
}

TEST(Color, OutputConversionLeavesAlpha) {
    const ColorPipeline p = pipeline("", "ACEScg");
    Image img(1, 1, 4);
    img.pixels = {1, 0, 0, 0.25f};
    p.to_output(img);
    EXPECT_NEAR(img.pixels[0], 0.613097f, 2e-5f);
    EXPECT_EQ(img.pixels[3], 0.25f);
    Image same(1, 1, 4);
    same.pixels = {0.3f, 0.2f, 0.1f, 1};
    ColorPipeline::builtin().to_output(same);  // output = working: untouched
    EXPECT_EQ(same.pixels[0], 0.3f);
}

TEST(Color, PreviewViews) {
    Image img(3, 1, 4);
    img.pixels = {0.18f, 0.18f, 0.18f, 1, 1, 1, 1, 1, 16, 16, 16, 1};
    const Image standard = ColorPipeline::builtin().to_display(img);
    ASSERT_EQ(standard.channels, 3);
    EXPECT_NEAR(standard.pixels[0], iec_linear_to_srgb(0.18), 1e-6);  // 0.4614
    EXPECT_FLOAT_EQ(standard.pixels[3], 1.0f);
    EXPECT_FLOAT_EQ(standard.pixels[6], 1.0f);  // clipped
    // One stop of exposure doubles the linear value first.
    EXPECT_NEAR(ColorPipeline::builtin().to_display(img, 1).pixels[0], iec_linear_to_srgb(0.36),
                1e-6);
    // The ACES view tone-maps: mid grey darker than plain sRGB, highlights rolled off
    // below white but still ordered.
    const Image aces = pipeline("", "", "ACES 1.0 - SDR Video").to_display(img);
    EXPECT_LT(aces.pixels[0], standard.pixels[0] - 0.05f);
    EXPECT_GT(aces.pixels[0], 0.2f);
    EXPECT_LT(aces.pixels[3], aces.pixels[6]);
    EXPECT_LT(aces.pixels[6], 1.0f);
}

TEST(Color, BadChoicesNameWhatIsAvailable) {
    auto message = [](const ColorSettings& s) {
        try {
            ColorPipeline p(s);
        } catch (const SceneError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    ColorSettings s;
    s.config = "builtin";
    s.working_space = "nope";
    EXPECT_NE(message(s).find("--working-space 'nope'"), std::string::npos) << message(s);
    EXPECT_NE(message(s).find("ACEScg"), std::string::npos) << message(s);
    s.working_space = "sRGB";  // encoded, not linear
    EXPECT_NE(message(s).find("not a linear"), std::string::npos) << message(s);
    s.working_space = "Raw";
    EXPECT_NE(message(s).find("data"), std::string::npos) << message(s);
    s.working_space = "";
    s.view = "Filmic";
    EXPECT_NE(message(s).find("Standard, ACES 1.0 - SDR Video"), std::string::npos) << message(s);
    s.view = "";
    s.look = "Punchy";
    EXPECT_NE(message(s).find("--look 'Punchy'"), std::string::npos) << message(s);
    s.look = "";
    s.config = "/no/such/config.ocio";
    EXPECT_NE(message(s).find("/no/such/config.ocio: cannot load"), std::string::npos)
        << message(s);
}

// Debian's blender-data puts it here; Blender's own builds under <version>/datafiles.
std::string blender_config() {
    namespace fs = std::filesystem;
    const fs::path debian = "/usr/share/blender/datafiles/colormanagement/config.ocio";
    if (fs::exists(debian)) return debian.string();
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator("/usr/share/blender", ec)) {
        const fs::path p = entry.path() / "datafiles/colormanagement/config.ocio";
        if (fs::exists(p)) return p.string();
    }
    return "";
}

TEST(Color, BlenderConfigLoadsAndItsViewsWork) {
    const std::string file = blender_config();
    // scripts/setup.sh --test (which scripts/test.sh runs) installs it: a missing config
    // is a broken test set-up, not a reason to skip.
    ASSERT_FALSE(file.empty())
        << "Blender's config.ocio is not installed (Debian package blender-data)";
    ColorSettings s;
    s.config = file;
    const ColorPipeline p(s);
    EXPECT_EQ(p.working_space(), "Linear");  // its scene_linear role
    EXPECT_TRUE(p.working_is_rec709());      // so glTF colours pass unchanged
    EXPECT_EQ(p.display(), "sRGB");
    EXPECT_EQ(p.view(), "Standard");
    ASSERT_TRUE(p.output_chromaticities());
    expect_chromaticities(*p.output_chromaticities(), rec709_chromaticities(), 1e-6f);

    Image img(3, 1, 4);
    img.pixels = {0.18f, 0.18f, 0.18f, 1, 4, 4, 4, 1, 0.02f, 0.02f, 0.02f, 1};
    // Standard is the sRGB curve (a 1D LUT in Blender's config).
    const Image standard = p.to_display(img);
    EXPECT_NEAR(standard.pixels[0], 0.461356f, 2e-3f);
    s.view = "Filmic";
    const Image filmic = ColorPipeline(s).to_display(img);
    EXPECT_GT(std::abs(filmic.pixels[0] - standard.pixels[0]), 0.02f);
    EXPECT_LT(filmic.pixels[3], 0.99f);  // Filmic keeps 4.0 below white
    s.look = "Medium High Contrast";
    const Image contrast = ColorPipeline(s).to_display(img);
    // Contrast looks pivot about mid grey; the shadows move.
    EXPECT_LT(contrast.pixels[6], filmic.pixels[6] - 0.01f);

    // Its ACEScg agrees with the built-in one.
    s = ColorSettings{};
    s.config = file;
    s.working_space = "Linear ACEScg";
    s.output_space = "Linear ACEScg";
    const ColorPipeline cg(s);
    EXPECT_LT(cg.rec709_to_working().max_difference(pipeline("ACEScg").rec709_to_working()), 1e-3);
    ASSERT_TRUE(cg.output_chromaticities());
    expect_chromaticities(*cg.output_chromaticities(), ap1_chromaticities(), 1e-6f);
}

TEST(Color, OcioVariableSelectsTheConfigAndBuiltinOverridesIt) {
    const std::string file = blender_config();
    // scripts/setup.sh --test (which scripts/test.sh runs) installs it: a missing config
    // is a broken test set-up, not a reason to skip.
    ASSERT_FALSE(file.empty())
        << "Blender's config.ocio is not installed (Debian package blender-data)";
    const char* old = std::getenv("OCIO");
    const std::string saved = old ? old : "";
    setenv("OCIO", file.c_str(), 1);
    const ColorPipeline from_env{ColorSettings{}};
    ColorSettings builtin;
    builtin.config = "builtin";
    const ColorPipeline forced(builtin);
    if (old)
        setenv("OCIO", saved.c_str(), 1);
    else
        unsetenv("OCIO");
    EXPECT_EQ(from_env.config_source(), "$OCIO=" + file);
    EXPECT_EQ(from_env.working_space(), "Linear");
    EXPECT_EQ(forced.working_space(), "Linear Rec.709 (sRGB)");
}

}  // namespace
}  // namespace penumbra
