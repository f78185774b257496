#include "io/color/color_config.h"

#include <string>
#include <vector>

namespace penumbra {

namespace {

OCIO::TransformRcPtr builtin(const char* style,
                             OCIO::TransformDirection dir = OCIO::TRANSFORM_DIR_FORWARD) {
    OCIO::BuiltinTransformRcPtr t = OCIO::BuiltinTransform::Create();
    t->setStyle(style);
    t->setDirection(dir);
    return t;
}

OCIO::TransformRcPtr group(const std::vector<OCIO::TransformRcPtr>& children) {
    OCIO::GroupTransformRcPtr g = OCIO::GroupTransform::Create();
    for (const OCIO::TransformRcPtr& t : children) g->appendTransform(t);
    return g;
}

// ACEScg (AP1) to the reference, linear Rec.709, with Bradford D60 -> D65 adaptation.
OCIO::TransformRcPtr ap1_to_rec709() { return builtin("UTILITY - ACES-AP1_to_LINEAR-REC709_BFD"); }

// ACES2065-1 (AP0) to ACEScg goes through the builtin ACEScg_to_ACES2065-1, inverted.
OCIO::TransformRcPtr ap0_to_ap1() {
    return builtin("ACEScg_to_ACES2065-1", OCIO::TRANSFORM_DIR_INVERSE);
}

OCIO::ColorSpaceRcPtr space(const char* name, const char* family, const char* encoding,
                            const char* description, const std::vector<const char*>& aliases = {},
                            OCIO::ReferenceSpaceType ref = OCIO::REFERENCE_SPACE_SCENE) {
    OCIO::ColorSpaceRcPtr cs = OCIO::ColorSpace::Create(ref);
    cs->setName(name);
    cs->setFamily(family);
    cs->setEncoding(encoding);
    cs->setDescription(description);
    for (const char* a : aliases) cs->addAlias(a);
    return cs;
}

OCIO::ConstConfigRcPtr make_config() {
    OCIO::ConfigRcPtr config = OCIO::Config::Create();
    config->setMajorVersion(2);
    config->setMinorVersion(1);
    config->setName("penumbra-builtin");
    config->setDescription(
        "penumbra's built-in config: linear Rec.709 reference (glTF's space), ACES spaces "
        "and an sRGB display, from OCIO 2.1 builtin transforms");

    auto lin = space(kLinearRec709, "Linear", "scene-linear",
                     "Linear Rec.709 primaries, D65 white: glTF's colour space",
                     {"lin_rec709", "lin_srgb", "linear"});
    config->addColorSpace(lin);

    auto acescg =
        space(kAcescg, "ACES", "scene-linear", "ACES AP1 primaries, linear", {"acescg", "lin_ap1"});
    acescg->setTransform(ap1_to_rec709(), OCIO::COLORSPACE_DIR_TO_REFERENCE);
    config->addColorSpace(acescg);

    auto aces = space(kAces2065, "ACES", "scene-linear", "ACES AP0 primaries, linear",
                      {"aces2065-1", "aces", "lin_ap0"});
    aces->setTransform(group({ap0_to_ap1(), ap1_to_rec709()}), OCIO::COLORSPACE_DIR_TO_REFERENCE);
    config->addColorSpace(aces);

    auto acescct =
        space("ACEScct", "ACES", "log", "ACEScct: ACES log encoding on AP1", {"acescct"});
    acescct->setTransform(group({builtin("ACEScct_to_ACES2065-1"), ap0_to_ap1(), ap1_to_rec709()}),
                          OCIO::COLORSPACE_DIR_TO_REFERENCE);
    config->addColorSpace(acescct);

    // IEC 61966-2-1: a linear segment below 0.04045, then ((v + 0.055) / 1.055)^2.4.
    // The forward direction decodes (encoded to linear).
    auto srgb = space(kSrgbEncoded, "Encoded", "sdr-video",
                      "sRGB-encoded Rec.709: 8-bit colour textures, images for sRGB screens",
                      {"srgb_texture", "srgb_encoded"});
    OCIO::ExponentWithLinearTransformRcPtr curve = OCIO::ExponentWithLinearTransform::Create();
    curve->setGamma({2.4, 2.4, 2.4, 1.0});
    curve->setOffset({0.055, 0.055, 0.055, 0.0});
    srgb->setTransform(curve, OCIO::COLORSPACE_DIR_TO_REFERENCE);
    config->addColorSpace(srgb);

    auto raw =
        space("Raw", "Data", "data", "Non-colour data, never converted", {"raw", "Non-Color"});
    raw->setIsData(true);
    config->addColorSpace(raw);

    // Display-referred spaces; the display reference is CIE XYZ with a D65 white.
    config->addColorSpace(space("CIE-XYZ-D65", "Display", "display-linear",
                                "CIE XYZ, D65 white: the display reference", {"cie_xyz_d65"},
                                OCIO::REFERENCE_SPACE_DISPLAY));
    auto srgb_display =
        space("sRGB - Display", "Display", "sdr-video", "sRGB display (piecewise sRGB curve)", {},
              OCIO::REFERENCE_SPACE_DISPLAY);
    srgb_display->setTransform(builtin("DISPLAY - CIE-XYZ-D65_to_sRGB"),
                               OCIO::COLORSPACE_DIR_FROM_REFERENCE);
    config->addColorSpace(srgb_display);

    // View transforms from the scene reference (linear Rec.709) to XYZ D65. The first
    // is the default for conversions between scene- and display-referred spaces.
    auto untonemapped = OCIO::ViewTransform::Create(OCIO::REFERENCE_SPACE_SCENE);
    untonemapped->setName("Un-tone-mapped");
    untonemapped->setDescription("Colorimetric: scene values shown as they are, clipped");
    untonemapped->setTransform(
        group({builtin("UTILITY - ACES-AP1_to_LINEAR-REC709_BFD", OCIO::TRANSFORM_DIR_INVERSE),
               builtin("UTILITY - ACES-AP1_to_CIE-XYZ-D65_BFD")}),
        OCIO::VIEWTRANSFORM_DIR_FROM_REFERENCE);
    config->addViewTransform(untonemapped);
    auto aces_sdr = OCIO::ViewTransform::Create(OCIO::REFERENCE_SPACE_SCENE);
    aces_sdr->setName("ACES 1.0 - SDR Video");
    aces_sdr->setDescription("ACES 1.0 RRT and SDR video ODT: a filmic tone scale");
    aces_sdr->setTransform(
        group({builtin("UTILITY - ACES-AP1_to_LINEAR-REC709_BFD", OCIO::TRANSFORM_DIR_INVERSE),
               builtin("ACEScg_to_ACES2065-1"),
               builtin("ACES-OUTPUT - ACES2065-1_to_CIE-XYZ-D65 - SDR-VIDEO_1.0")}),
        OCIO::VIEWTRANSFORM_DIR_FROM_REFERENCE);
    config->addViewTransform(aces_sdr);

    // "Standard" names the sRGB-encoded scene space directly: exactly the sRGB curve on
    // the (clipped) linear values, as an 8-bit sRGB file expects.
    config->addDisplayView(kSrgbDisplay, "Standard", kSrgbEncoded, "");
    config->addDisplayView(kSrgbDisplay, "ACES 1.0 - SDR Video", "ACES 1.0 - SDR Video",
                           "sRGB - Display", "", "", "");
    config->addDisplayView(kSrgbDisplay, "Raw", "Raw", "");

    config->setRole(OCIO::ROLE_REFERENCE, kLinearRec709);
    config->setRole(OCIO::ROLE_SCENE_LINEAR, kLinearRec709);
    config->setRole(OCIO::ROLE_RENDERING, kLinearRec709);
    config->setRole(OCIO::ROLE_DEFAULT, kLinearRec709);
    config->setRole(OCIO::ROLE_COLOR_PICKING, kSrgbEncoded);
    config->setRole(OCIO::ROLE_TEXTURE_PAINT, kSrgbEncoded);
    config->setRole(OCIO::ROLE_MATTE_PAINT, kSrgbEncoded);
    config->setRole(OCIO::ROLE_DATA, "Raw");
    config->setRole(OCIO::ROLE_COMPOSITING_LOG, "ACEScct");
    config->setRole(OCIO::ROLE_COLOR_TIMING, "ACEScct");
    config->setRole(OCIO::ROLE_INTERCHANGE_SCENE, kAces2065);
    config->setRole(OCIO::ROLE_INTERCHANGE_DISPLAY, "CIE-XYZ-D65");
    config->validate();
    return config;
}

}  // namespace

OCIO::ConstConfigRcPtr builtin_config() {
    // Built once; OCIO configs are immutable once shared and safe to use from threads.
    static const OCIO::ConstConfigRcPtr config = make_config();
    return config;
}

}  // namespace penumbra
