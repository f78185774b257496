// Real files (../shared/scenes/wild/ and khronos/, read in place): every one loads with
// no "unsupported extension" error or warning for a material or texture extension; the
// required-extension files (unlit, specular-glossiness, WebP) load with what they need.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "core/error.h"
#include "io/gltf/gltf_loader.h"
#include "support/paths.h"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

// Every .gltf and .glb under scenes/wild/*/ and scenes/khronos/, sorted.
std::vector<std::string> shared_scenes() {
    std::vector<std::string> files;
    for (const char* dir : {"scenes/wild", "scenes/khronos"})
        for (const auto& e : fs::recursive_directory_iterator(test::shared_path(dir))) {
            const std::string ext = e.path().extension().string();
            if (e.is_regular_file() && (ext == ".gltf" || ext == ".glb"))
                files.push_back(e.path().string());
        }
    std::sort(files.begin(), files.end());
    return files;
}

size_t count_lines(const std::string& text, const std::string& what) {
    size_t n = 0;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) n += line.find(what) != std::string::npos;
    return n;
}

TEST(GltfMaterialWild, EveryFileLoadsWithoutAnUnsupportedMaterialOrTextureExtension) {
    const std::vector<std::string> files = shared_scenes();
    ASSERT_GE(files.size(), 20u) << "the shared scenes are missing";
    for (const std::string& path : files) {
        SCOPED_TRACE(path);
        testing::internal::CaptureStderr();
        std::string error;
        try {
            load_gltf(path);
        } catch (const SceneError& e) {
            error = e.what();
        }
        const std::string log = testing::internal::GetCapturedStderr();
        EXPECT_EQ(error, "");  // Draco and meshopt files too (gltf_draco_test.cpp etc.)
        // Whatever else a file lacks, no material or texture extension may be reported.
        std::istringstream lines(log + "\n" + error);
        for (std::string line; std::getline(lines, line);) {
            if (line.find("unsupported") == std::string::npos &&
                line.find("ignor") == std::string::npos)
                continue;
            EXPECT_TRUE(line.find("KHR_materials_") == std::string::npos &&
                        line.find("KHR_texture_transform") == std::string::npos &&
                        line.find("EXT_texture_webp") == std::string::npos)
                << line;
        }
        // Recorded for the report; the count itself is not a pass criterion.
        std::cout << "[ warnings ] " << fs::path(path).filename().string() << ": "
                  << count_lines(log, "warning: ") << "\n";
        if (count_lines(log, "warning: ")) std::cout << log;
    }
}

std::string wild(const std::string& rel) { return test::shared_path("scenes/wild/" + rel); }

TEST(GltfMaterialWild, UnlitAndSpecularGlossinessFiles) {
    const Scene unlit = load_gltf(wild("UnlitTest/UnlitTest.gltf"));
    ASSERT_EQ(unlit.materials.size(), 2u);
    for (const MaterialDesc& m : unlit.materials) EXPECT_TRUE(m.unlit) << m.name;
    EXPECT_FLOAT_EQ(unlit.materials[0].base_color.y, 0.217637640824031f);

    const Scene sg = load_gltf(wild("SpecGlossVsMetalRough/SpecGlossVsMetalRough.gltf"));
    size_t specgloss = 0;
    for (const MaterialDesc& m : sg.materials) {
        if (!m.specular_glossiness) continue;
        ++specgloss;
        EXPECT_EQ(m.metallic, 0.0f) << m.name;
        EXPECT_TRUE(m.base_color_texture.valid()) << m.name;
    }
    EXPECT_EQ(specgloss, 2u);
    // The bottle: a specular-glossiness texture with factors at their defaults; the label:
    // black specular, glossiness 0.
    const auto bottle =
        std::find_if(sg.materials.begin(), sg.materials.end(),
                     [](const MaterialDesc& m) { return m.name == "BottleMat_SpecGloss"; });
    ASSERT_NE(bottle, sg.materials.end());
    EXPECT_TRUE(bottle->specular_glossiness_texture.valid());
    EXPECT_EQ(bottle->roughness, 0.0f);
    const auto label =
        std::find_if(sg.materials.begin(), sg.materials.end(),
                     [](const MaterialDesc& m) { return m.name == "Label Material SpecGloss"; });
    ASSERT_NE(label, sg.materials.end());
    EXPECT_EQ(label->roughness, 1.0f);
    EXPECT_TRUE(is_black(label->specular_color));
}

const MaterialDesc& named(const Scene& s, const std::string& name) {
    for (const MaterialDesc& m : s.materials)
        if (m.name == name) return m;
    ADD_FAILURE() << "no material " << name;
    return s.materials.at(0);
}

// Values read from each file's JSON, as exporters wrote them.
TEST(GltfMaterialWild, ExtensionValuesOfRealFiles) {
    const Scene golf = load_gltf(wild("GolfBall/GolfBall.glb"));
    EXPECT_EQ(golf.materials.at(0).clearcoat, 1.0f);
    EXPECT_EQ(golf.materials.at(0).clearcoat_roughness, 0.0f);
    EXPECT_TRUE(golf.materials.at(0).clearcoat_normal_texture.valid());

    const Scene cloth = load_gltf(wild("SheenCloth/SheenCloth.gltf"));
    const MaterialDesc& sheen = named(cloth, "SheenClothMat");
    EXPECT_EQ(sheen.sheen_color.x, 1.0f);
    EXPECT_EQ(sheen.sheen_roughness, 1.0f);
    ASSERT_TRUE(sheen.sheen_color_texture.valid());
    EXPECT_EQ(sheen.sheen_color_texture.scale.x, 30.0f);
    EXPECT_EQ(sheen.sheen_color_texture.scale.y, -30.0f);
    EXPECT_TRUE(sheen.sheen_roughness_texture.valid());

    const Scene spec = load_gltf(wild("SpecularTest/SpecularTest.glb"));
    EXPECT_TRUE(named(spec, "M2_SpecTex").specular_texture.valid());
    EXPECT_TRUE(named(spec, "M4_whiteTex").specular_color_texture.valid());
    EXPECT_FLOAT_EQ(named(spec, "M1.3_specFac").specular, 0.212231f);
    // Above 1, as KHR_materials_specular allows.
    EXPECT_EQ(named(spec, "M7.5_HDR").specular_color.y, 25.0f);

    const Scene att = load_gltf(wild("AttenuationTest/AttenuationTest.glb"));
    const MaterialDesc& tex = named(att, "R3_ThicknessTex_Mat");
    EXPECT_EQ(tex.thickness, 2.0f);
    EXPECT_TRUE(tex.thickness_texture.valid());
    EXPECT_FLOAT_EQ(tex.attenuation_color.y, 0.5f);
    EXPECT_EQ(named(att, "R5_Attenuation_0.25").attenuation_distance, 4.0f);
    EXPECT_EQ(named(att, "R1_Sample_1.0").attenuation_distance, INFINITY);

    const Scene aniso = load_gltf(wild("AnisotropyStrengthTest/AnisotropyStrengthTest.glb"));
    ASSERT_EQ(aniso.materials.size(), 50u);
    EXPECT_FLOAT_EQ(aniso.materials[3].anisotropy_strength, 0.5f);
    EXPECT_EQ(aniso.materials[6].anisotropy_strength, 1.0f);
    EXPECT_EQ(aniso.materials[49].anisotropy_strength, 0.0f);
}

// Both files decode the WebP image (the fallback file's PNG is not used): the same
// pixels, a logo rather than a flat colour.
TEST(GltfMaterialWild, WebpTexturesRequiredAndWithFallback) {
    const Scene req = load_gltf(wild("CesiumBoxWebp/CesiumBoxWebp-Required.gltf"));
    const Scene fb = load_gltf(wild("CesiumBoxWebp/CesiumBoxWebp-WithFallbackPNG.gltf"));
    for (const Scene* s : {&req, &fb}) {
        ASSERT_EQ(s->materials.size(), 1u);
        ASSERT_TRUE(s->materials[0].base_color_texture.valid());
        ASSERT_EQ(s->images.size(), 1u);
    }
    const Image a = req.images[0].to_image();
    const Image b = fb.images[0].to_image();
    ASSERT_GT(a.width, 16);
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    ASSERT_EQ(a.channels, b.channels);
    EXPECT_EQ(a.pixels, b.pixels);
    const auto [lo, hi] = std::minmax_element(a.pixels.begin(), a.pixels.end());
    EXPECT_GT(*hi - *lo, 0.5f);
}

}  // namespace
}  // namespace penumbra
