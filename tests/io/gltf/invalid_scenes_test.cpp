// Every file in scenes/invalid/ fails to load with its expected one-line message; the
// table below is the one in scenes/invalid/README.md.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

#include "core/error.h"
#include "io/gltf/gltf_loader.h"
#include "support/paths.h"

namespace penumbra {
namespace {

struct InvalidScene {
    const char* file;
    const char* expected;  // substring of the message after "<path>: "
};

const InvalidScene kInvalidScenes[] = {
    {"accessor-out-of-range.gltf",
     "meshes[0].primitives[0]: POSITION accessor index 5 out of range (1 accessors)"},
    {"animation-bad-interpolation.gltf",
     "animations[0].samplers[0]: interpolation 'SMOOTH' is not LINEAR, STEP or CUBICSPLINE"},
    {"animation-matrix-node.gltf",
     "animations[0].channels[0]: animates nodes[0], which has a matrix (animated nodes must use TRS)"},
    {"animation-output-count.gltf",
     "animations[0].samplers[0]: output accessor has 2 elements; 3 LINEAR keys of translation need 3"},
    {"animation-times-not-increasing.gltf",
     "animations[0].samplers[0]: input times are not strictly increasing (key 2)"},
    {"animation-weights-without-targets.gltf",
     "animations[0].channels[0]: animates the weights of nodes[0], whose mesh has no morph targets"},
    {"bad-material-index.gltf",
     "meshes[0].primitives[0]: material index 1 out of range (1 materials)"},
    {"buffer-too-short.gltf",
     "accessors[0]: bufferView[0] range [0, 36) exceeds buffer 0 of 24 bytes"},
    {"index-out-of-range.gltf", "meshes[0].primitives[0]: index 7 out of range (3 vertices)"},
    {"malformed.gltf", "parse error at line 11"},
    {"material-out-of-range.gltf",
     "materials[0].extensions.KHR_materials_volume: attenuationDistance 0 is outside (0, +inf)"},
    {"missing-image.gltf", "images[0]: cannot read image file 'missing.png'"},
    {"nan-position.gltf", "meshes[0].primitives[0]: POSITION element 1 is not finite"},
    {"nan-tangent.gltf", "meshes[0].primitives[0]: TANGENT element 2 is not finite"},
    {"node-cycle.gltf", "nodes[0]: reached twice in the node tree"},
    {"skin-joint-out-of-range.gltf", "skins[0]: joint node index 5 out of range (1 nodes)"},
    {"unsupported-extension.gltf",
     "extensionsRequired: unsupported extension 'EXT_lights_image_based'"},
    {"variant-bad-material.gltf",
     "meshes[0].primitives[0].extensions.KHR_materials_variants.mappings[0]: material index 3 "
     "out of range (1 materials)"},
    {"wrong-position-type.gltf",
     "meshes[0].primitives[0]: POSITION accessor 0 is VEC2 of float; expected VEC3"},
    {"zero-positions.gltf", "meshes[0].primitives[0]: POSITION accessor has 0 elements"},
};

class InvalidScenesTest : public ::testing::TestWithParam<InvalidScene> {};

TEST_P(InvalidScenesTest, FailsWithItsMessage) {
    const std::string path = test::source_path(std::string("scenes/invalid/") + GetParam().file);
    ASSERT_TRUE(std::filesystem::exists(path)) << path;
    try {
        load_gltf(path);
        FAIL() << "no error for " << path;
    } catch (const SceneError& e) {
        const std::string msg = e.what();
        EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << msg;
        EXPECT_NE(msg.find(GetParam().expected), std::string::npos) << msg;
        EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    }
}

INSTANTIATE_TEST_SUITE_P(InvalidScenes, InvalidScenesTest, ::testing::ValuesIn(kInvalidScenes),
                         [](const auto& info) {
                             std::string name = info.param.file;
                             name = name.substr(0, name.find('.'));
                             for (char& c : name)
                                 if (c == '-') c = '_';
                             return name;
                         });

// The table above, the README's table and the folder's files agree.
TEST(InvalidScenes, TableMatchesReadmeAndFolder) {
    std::ifstream f(test::source_path("scenes/invalid/README.md"));
    const std::string readme{std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
    std::set<std::string> listed;
    for (const InvalidScene& s : kInvalidScenes) {
        listed.insert(s.file);
        const std::string row = std::string("| `") + s.file + "` | `" + s.expected + "` |";
        EXPECT_NE(readme.find(row), std::string::npos) << "README lacks the row " << row;
    }
    for (const auto& entry :
         std::filesystem::directory_iterator(test::source_path("scenes/invalid"))) {
        const std::string name = entry.path().filename().string();
        if (name == "README.md") continue;
        EXPECT_TRUE(listed.count(name)) << name << " is not in the table";
    }
}

}  // namespace
}  // namespace penumbra
