// KHR material extension values outside their schemas' ranges (clamped with a warning,
// an error under --strict), wrong JSON types and bad texture references (errors naming
// the material, the extension and the key).
#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "support/material_gltf.h"

namespace penumbra {
namespace {

using test::load_with_material;

std::string error_of(const std::string& material, bool strict = false) {
    try {
        load_with_material(material, Mat3::identity(), strict);
    } catch (const SceneError& e) {
        const std::string what = e.what();
        const size_t at = what.find("materials[0]");
        return at == std::string::npos ? what : what.substr(at);
    }
    return "(loaded)";
}

std::string ext(const char* name, const std::string& body) {
    return std::string(R"({"extensions": {")") + name + "\": " + body + "}}";
}

// Each bound: the value on it loads; a value just past it loads clamped (with a warning)
// where the range is closed there, and is an error naming the element, the key and the
// range under --strict, or always where no clamp mends it (an open bound, float range).
TEST(GltfMaterialRanges, ValuesOutsideTheSpecRangeAreClampedOrErrors) {
    struct Case {
        const char *name, *ok, *bad, *message;
    };
    const Case cases[] = {
        {"KHR_materials_clearcoat", R"({"clearcoatFactor": 1})", R"({"clearcoatFactor": 1.001})",
         "clearcoatFactor 1.001 is outside [0, 1]"},
        {"KHR_materials_clearcoat", R"({"clearcoatRoughnessFactor": 0})",
         R"({"clearcoatRoughnessFactor": -0.001})",
         "clearcoatRoughnessFactor -0.001 is outside [0, 1]"},
        {"KHR_materials_sheen", R"({"sheenColorFactor": [1, 1, 0]})",
         R"({"sheenColorFactor": [0.5, 1.01, 0]})", "sheenColorFactor[1] 1.01 is outside [0, 1]"},
        {"KHR_materials_sheen", R"({"sheenRoughnessFactor": 1})", R"({"sheenRoughnessFactor": 2})",
         "sheenRoughnessFactor 2 is outside [0, 1]"},
        {"KHR_materials_volume", R"({"thicknessFactor": 0})", R"({"thicknessFactor": -1})",
         "thicknessFactor -1 is outside [0, +inf)"},
        {"KHR_materials_volume", R"({"attenuationDistance": 1e-6})",
         R"({"attenuationDistance": 0})", "attenuationDistance 0 is outside (0, +inf)"},
        {"KHR_materials_volume", R"({"attenuationColor": [0, 0, 1]})",
         R"({"attenuationColor": [-0.1, 0, 1]})", "attenuationColor[0] -0.1 is outside [0, 1]"},
        {"KHR_materials_iridescence", R"({"iridescenceFactor": 1})",
         R"({"iridescenceFactor": 1.5})", "iridescenceFactor 1.5 is outside [0, 1]"},
        {"KHR_materials_iridescence", R"({"iridescenceIor": 1})", R"({"iridescenceIor": 0.99})",
         "iridescenceIor 0.99 is outside [1, +inf)"},
        {"KHR_materials_iridescence", R"({"iridescenceThicknessMinimum": 0})",
         R"({"iridescenceThicknessMinimum": -1})",
         "iridescenceThicknessMinimum -1 is outside [0, +inf)"},
        {"KHR_materials_iridescence", R"({"iridescenceThicknessMaximum": 0})",
         R"({"iridescenceThicknessMaximum": -5})",
         "iridescenceThicknessMaximum -5 is outside [0, +inf)"},
        {"KHR_materials_anisotropy", R"({"anisotropyStrength": 1})",
         R"({"anisotropyStrength": -0.1})", "anisotropyStrength -0.1 is outside [0, 1]"},
        {"KHR_materials_anisotropy", R"({"anisotropyRotation": -1e38})",
         R"({"anisotropyRotation": 1e39})", "anisotropyRotation 1e+39 is outside the float range"},
        {"KHR_materials_dispersion", R"({"dispersion": 0})", R"({"dispersion": -0.5})",
         "dispersion -0.5 is outside [0, +inf)"},
        {"KHR_materials_diffuse_transmission", R"({"diffuseTransmissionFactor": 1})",
         R"({"diffuseTransmissionFactor": 1.2})",
         "diffuseTransmissionFactor 1.2 is outside [0, 1]"},
        {"KHR_materials_diffuse_transmission", R"({"diffuseTransmissionColorFactor": [1, 1, 1]})",
         R"({"diffuseTransmissionColorFactor": [1, 1, 1.2]})",
         "diffuseTransmissionColorFactor[2] 1.2 is outside [0, 1]"},
        {"KHR_materials_specular", R"({"specularFactor": 1})", R"({"specularFactor": 1.5})",
         "specularFactor 1.5 is outside [0, 1]"},
        {"KHR_materials_specular", R"({"specularColorFactor": [0, 7, 0]})",
         R"({"specularColorFactor": [0, -1, 0]})",
         "specularColorFactor[1] -1 is outside [0, +inf)"},
        {"KHR_materials_pbrSpecularGlossiness", R"({"diffuseFactor": [1, 1, 1, 0]})",
         R"({"diffuseFactor": [1, 1, 1, 1.5]})", "diffuseFactor[3] 1.5 is outside [0, 1]"},
        {"KHR_materials_pbrSpecularGlossiness", R"({"specularFactor": [1, 0, 0]})",
         R"({"specularFactor": [2, 0, 0]})", "specularFactor[0] 2 is outside [0, 1]"},
        {"KHR_materials_pbrSpecularGlossiness", R"({"glossinessFactor": 0})",
         R"({"glossinessFactor": -0.1})", "glossinessFactor -0.1 is outside [0, 1]"},
        {"KHR_materials_transmission", R"({"transmissionFactor": 1})",
         R"({"transmissionFactor": 1.5})", "transmissionFactor 1.5 is outside [0, 1]"},
        {"KHR_materials_emissive_strength", R"({"emissiveStrength": 0})",
         R"({"emissiveStrength": -2})", "emissiveStrength -2 is outside [0, +inf)"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.bad);
        const std::string message =
            "materials[0].extensions." + std::string(c.name) + ": " + c.message;
        const std::string m = c.message;
        const bool mendable = m.find("(0, +inf)") == std::string::npos &&
                              m.find("the float range") == std::string::npos;
        EXPECT_EQ(error_of(ext(c.name, c.ok)), "(loaded)");
        EXPECT_EQ(error_of(ext(c.name, c.ok), true), "(loaded)");
        if (mendable) {
            EXPECT_EQ(error_of(ext(c.name, c.bad)), "(loaded)");
            EXPECT_EQ(error_of(ext(c.name, c.bad), true), message + " [--strict]");
        } else {
            EXPECT_EQ(error_of(ext(c.name, c.bad)), message);
        }
    }
}

// The clamp lands on the violated bound, per component.
TEST(GltfMaterialRanges, OvershootingValuesAreClampedToTheirBound) {
    const Scene a = load_with_material(ext("KHR_materials_clearcoat", R"({"clearcoatFactor": 1.001})"));
    EXPECT_EQ(a.materials[0].clearcoat, 1.0f);
    const Scene b = load_with_material(
        ext("KHR_materials_sheen", R"({"sheenColorFactor": [0.5, 1.01, -0.2]})"));
    EXPECT_EQ(b.materials[0].sheen_color, Spectrum(0.5f, 1.0f, 0.0f));
    const Scene c =
        load_with_material(ext("KHR_materials_iridescence", R"({"iridescenceIor": 0.99})"));
    EXPECT_EQ(c.materials[0].iridescence_ior, 1.0f);
}

TEST(GltfMaterialRanges, WrongTypesAndBadTexturesAreErrors) {
    const std::string cc = "materials[0].extensions.KHR_materials_clearcoat";
    EXPECT_EQ(error_of(ext("KHR_materials_clearcoat", R"({"clearcoatFactor": "1"})")),
              cc + ": clearcoatFactor is not a number");
    EXPECT_EQ(error_of(ext("KHR_materials_volume", R"({"attenuationColor": [1, 1]})")),
              "materials[0].extensions.KHR_materials_volume: attenuationColor must have 3 numbers");
    EXPECT_EQ(
        error_of(ext("KHR_materials_clearcoat", R"({"clearcoatNormalTexture": {"index": 3}})")),
        cc + ".clearcoatNormalTexture: texture index 3 out of range (1 textures)");
    EXPECT_EQ(error_of(ext("KHR_materials_sheen", R"({"sheenColorTexture": {"texCoord": 0}})")),
              "materials[0].extensions.KHR_materials_sheen.sheenColorTexture: must be a "
              "textureInfo with an integer index");
    EXPECT_EQ(error_of(ext("KHR_materials_pbrSpecularGlossiness",
                           R"({"specularGlossinessTexture": {"index": -1}})")),
              "materials[0].extensions.KHR_materials_pbrSpecularGlossiness."
              "specularGlossinessTexture: texture index -1 out of range (1 textures)");
    EXPECT_EQ(error_of(ext("KHR_materials_clearcoat",
                           R"({"clearcoatNormalTexture": {"index": 0, "scale": "x"}})")),
              cc + ".clearcoatNormalTexture: scale is not a number");
}

}  // namespace
}  // namespace penumbra
