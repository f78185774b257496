// Bad glTF input: every problem is a one-line SceneError "<file>: <element>: <problem>".
// One test per case, on files written here (scenes/invalid/ has the checked-in ones).
#include <gtest/gtest.h>

#include "core/error.h"
#include "io/gltf/gltf_loader.h"
#include "support/gltf_builder.h"

namespace penumbra {
namespace {

using test::BufferStorage;
using test::GltfBuilder;
using test::ScratchDir;

// Loads path and checks the message: the file first, then `expected`, on one line.
void expect_error(const std::string& path, const std::string& expected) {
    try {
        load_gltf(path);
        ADD_FAILURE() << "no error for " << path;
    } catch (const SceneError& e) {
        const std::string msg = e.what();
        EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << msg;
        EXPECT_NE(msg.find(expected), std::string::npos) << msg;
        EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    }
}

const std::vector<float> kTriangle = {0, 0, 0, 1, 0, 0, 0, 1, 0};

// A triangle whose POSITION is accessor 0, plus `members` before the mesh.
std::string write_triangle(const ScratchDir& dir, const std::string& prim_extra,
                           const std::string& members = "") {
    GltfBuilder b;
    b.add(kTriangle, test::kFloat, "VEC3");
    const std::string prim = R"({"attributes": {"POSITION": 0})" + prim_extra + "}";
    return b.write(dir, "t.gltf", members + test::one_mesh_scene(prim), BufferStorage::DataUri);
}

TEST(GltfErrors, MissingFile) {
    ScratchDir dir;
    const std::string path = dir.file("missing.gltf");
    try {
        load_gltf(path);
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()), path + ": cannot open file");
    }
}

TEST(GltfErrors, MalformedJson) {
    ScratchDir dir;
    expect_error(dir.write("bad.gltf", "{\n  \"asset\": {\"version\": \"2.0\"},\n  \"nodes\": [\n"),
                 "parse error");
}

TEST(GltfErrors, AccessorIndexOutOfRange) {
    ScratchDir dir;
    GltfBuilder b;
    b.add(kTriangle, test::kFloat, "VEC3");
    const std::string prim = R"({"attributes": {"POSITION": 0, "NORMAL": 7}})";
    expect_error(b.write(dir, "t.gltf", test::one_mesh_scene(prim), BufferStorage::DataUri),
                 "meshes[0].primitives[0]: NORMAL accessor index 7 out of range (1 accessors)");
}

TEST(GltfErrors, IndexOutOfRange) {
    ScratchDir dir;
    GltfBuilder b;
    b.add(kTriangle, test::kFloat, "VEC3");
    b.add(std::vector<uint16_t>{0, 1, 17}, test::kUShort, "SCALAR");
    const std::string prim = R"({"attributes": {"POSITION": 0}, "indices": 1})";
    expect_error(b.write(dir, "t.gltf", test::one_mesh_scene(prim), BufferStorage::DataUri),
                 "meshes[0].primitives[0]: index 17 out of range (3 vertices)");
}

TEST(GltfErrors, BufferTooShort) {
    ScratchDir dir;
    GltfBuilder b;
    b.bytes().resize(24);
    b.add_view(0, 36);
    b.add_accessor(0, 0, test::kFloat, "VEC3", 3);
    const std::string prim = R"({"attributes": {"POSITION": 0}})";
    expect_error(b.write(dir, "t.gltf", test::one_mesh_scene(prim), BufferStorage::DataUri),
                 "accessors[0]: bufferView[0] range [0, 36) exceeds buffer 0 of 24 bytes");
}

TEST(GltfErrors, AccessorExceedsBufferView) {
    ScratchDir dir;
    GltfBuilder b;
    b.bytes().resize(36);
    b.add_view(0, 36);
    b.add_accessor(0, 4, test::kFloat, "VEC3", 3);
    const std::string prim = R"({"attributes": {"POSITION": 0}})";
    expect_error(b.write(dir, "t.gltf", test::one_mesh_scene(prim), BufferStorage::DataUri),
                 "accessors[0]: byteOffset 4 + 3 elements of 12 bytes, stride 12, exceed "
                 "bufferView[0] of 36 bytes");
}

TEST(GltfErrors, NanPosition) {
    ScratchDir dir;
    GltfBuilder b;
    b.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, std::nanf(""), 0}, test::kFloat, "VEC3");
    const std::string prim = R"({"attributes": {"POSITION": 0}})";
    expect_error(b.write(dir, "t.gltf", test::one_mesh_scene(prim), BufferStorage::DataUri),
                 "meshes[0].primitives[0]: POSITION element 3 is not finite");
}

TEST(GltfErrors, ZeroPositions) {
    ScratchDir dir;
    GltfBuilder b;
    b.add(kTriangle, test::kFloat, "VEC3");
    b.add_accessor(0, 0, test::kFloat, "VEC3", 0);
    const std::string prim = R"({"attributes": {"POSITION": 1}})";
    expect_error(b.write(dir, "t.gltf", test::one_mesh_scene(prim), BufferStorage::DataUri),
                 "meshes[0].primitives[0]: POSITION accessor has 0 elements");
}

TEST(GltfErrors, UnsupportedRequiredExtension) {
    ScratchDir dir;
    const std::string members = R"("extensionsUsed": ["EXT_lights_image_based"],
        "extensionsRequired": ["EXT_lights_image_based"],)";
    expect_error(write_triangle(dir, "", members),
                 "extensionsRequired: unsupported extension 'EXT_lights_image_based'");
}

TEST(GltfErrors, WrongPositionType) {
    ScratchDir dir;
    GltfBuilder b;
    b.add(std::vector<float>{0, 0, 1, 0, 0, 1}, test::kFloat, "VEC2");
    const std::string prim = R"({"attributes": {"POSITION": 0}})";
    expect_error(b.write(dir, "t.gltf", test::one_mesh_scene(prim), BufferStorage::DataUri),
                 "meshes[0].primitives[0]: POSITION accessor 0 is VEC2 of float; expected VEC3");
}

TEST(GltfErrors, BadMaterialIndex) {
    ScratchDir dir;
    expect_error(write_triangle(dir, R"(, "material": 2)"),
                 "meshes[0].primitives[0]: material index 2 out of range (0 materials)");
}

TEST(GltfErrors, BadTextureIndex) {
    ScratchDir dir;
    const std::string members =
        R"("materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 3}}}],)";
    expect_error(write_triangle(dir, "", members),
                 "materials[0].pbrMetallicRoughness.baseColorTexture: texture index 3 out of "
                 "range (0 textures)");
}

TEST(GltfErrors, BadImageAndSamplerIndex) {
    ScratchDir dir;
    const std::string mat = R"("materials": [{"emissiveTexture": {"index": 0}}],)";
    expect_error(write_triangle(dir, "", mat + R"("textures": [{"source": 4}],)"),
                 "textures[0]: source index 4 out of range (0 images)");
    expect_error(write_triangle(dir, "", mat + R"("textures": [{"source": 0, "sampler": 1}],
                                 "images": [{"uri": "x.png"}],)"),
                 "textures[0]: sampler index 1 out of range (0 samplers)");
}

TEST(GltfErrors, MissingImageFile) {
    ScratchDir dir;
    const std::string members = R"("materials": [{"emissiveTexture": {"index": 0}}],
        "textures": [{"source": 0}], "images": [{"uri": "nowhere.png"}],)";
    expect_error(write_triangle(dir, "", members),
                 "images[0]: cannot read image file 'nowhere.png'");
}

TEST(GltfErrors, BadNodeReferences) {
    ScratchDir dir;
    GltfBuilder b;
    b.add(kTriangle, test::kFloat, "VEC3");
    const std::string mesh = R"("meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],)";
    expect_error(
        b.write(dir, "a.gltf", mesh + R"("nodes": [{"mesh": 1}], "scenes": [{"nodes": [0]}])",
                BufferStorage::DataUri),
        "nodes[0]: mesh index 1 out of range (1 meshes)");
    expect_error(
        b.write(dir, "b.gltf", mesh + R"("nodes": [{"camera": 0}], "scenes": [{"nodes": [0]}])",
                BufferStorage::DataUri),
        "nodes[0]: camera index 0 out of range (0 cameras)");
    expect_error(
        b.write(dir, "c.gltf", mesh + R"("nodes": [{"children": [5]}], "scenes": [{"nodes": [0]}])",
                BufferStorage::DataUri),
        "nodes[0]: child node index 5 out of range (1 nodes)");
    expect_error(b.write(dir, "d.gltf", mesh + R"("nodes": [{}], "scenes": [{"nodes": [0, 3]}])",
                         BufferStorage::DataUri),
                 "scenes[0]: node index 3 out of range (1 nodes)");
}

TEST(GltfErrors, NodeCycleAndSharedChild) {
    ScratchDir dir;
    GltfBuilder b;
    b.add(kTriangle, test::kFloat, "VEC3");
    const std::string mesh = R"("meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],)";
    expect_error(b.write(dir, "cycle.gltf",
                         mesh + R"("nodes": [{"children": [1]}, {"children": [0], "mesh": 0}],
                                   "scenes": [{"nodes": [0]}])",
                         BufferStorage::DataUri),
                 "nodes[0]: reached twice in the node tree");
    expect_error(b.write(dir, "shared.gltf",
                         mesh + R"("nodes": [{"children": [2]}, {"children": [2]}, {"mesh": 0}],
                                   "scenes": [{"nodes": [0, 1]}])",
                         BufferStorage::DataUri),
                 "nodes[2]: reached twice in the node tree");
}

TEST(GltfErrors, BadLightAndCamera) {
    ScratchDir dir;
    // tinygltf rejects this one itself; its message is passed on after the file name.
    expect_error(write_triangle(dir, "", R"("cameras": [{"type": "fisheye"}],)"),
                 "Invalid camera type: \"fisheye\"");
    GltfBuilder b;
    b.add(kTriangle, test::kFloat, "VEC3");
    const std::string members = R"("extensions": {"KHR_lights_punctual": {"lights": [
        {"type": "spot", "spot": {"innerConeAngle": 1.0, "outerConeAngle": 0.5}}]}},
        "nodes": [{"extensions": {"KHR_lights_punctual": {"light": 0}}},
                  {"extensions": {"KHR_lights_punctual": {"light": 1}}}],
        "scenes": [{"nodes": [1]}, {"nodes": [0]}])";
    const std::string path = b.write(dir, "l.gltf", members, BufferStorage::DataUri);
    expect_error(path, "nodes[1]: KHR_lights_punctual light index 1 out of range (1 lights)");
    try {
        load_gltf(path, {1});
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("extensions.KHR_lights_punctual.lights[0]: spot "
                                             "cone angles"),
                  std::string::npos)
            << e.what();
    }
}

TEST(GltfErrors, TruncatedGlb) {
    ScratchDir dir;
    expect_error(dir.write("cut.glb", std::string("glTF\x02\x00\x00\x00\x40\x00\x00\x00", 12)), "");
}

}  // namespace
}  // namespace penumbra
