// Out-of-spec but renderable data gets one summary warning per kind and file, with a
// count and an example: properties animated by several animations (Fox.glb), channels
// without a target node, skin weights that do not sum to one, nodes hidden by a zero scale,
// instanced skinned meshes, skins outside the scene. --strict makes each an error. (Mesh
// data: gltf_mesh_checks_test.)
#include <gtest/gtest.h>

#include "core/error.h"
#include "io/gltf/gltf_loader.h"
#include "support/gltf_builder.h"
#include "support/paths.h"

namespace penumbra {
namespace {

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

std::string warnings_of(const std::string& path) {
    testing::internal::CaptureStderr();
    load_gltf(path);
    return testing::internal::GetCapturedStderr();
}

std::string strict_error(const std::string& path) {
    GltfLoadOptions o;
    o.strict = true;
    try {
        load_gltf(path, o);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

// Fox.glb's three animations (Survey, Walk, Run) each drive the same 21 node properties:
// 42 overlaps (counted from its JSON: 21 properties x 2 later animations), one line.
TEST(GltfSummaryWarnings, FoxOverlappingAnimationsAreOneWarning) {
    const std::string path = test::shared_path("scenes/wild/Fox/Fox.glb");
    const std::string log = warnings_of(path);
    EXPECT_EQ(count(log, "warning: "), 1u) << log;
    EXPECT_EQ(count(log, path + ": animations: 42 node properties animated by several "
                                "animations; the first animation's channel is used (nodes["),
              1u)
        << log;
    EXPECT_EQ(count(log, "by animations[0] and animations[1]"), 3u) << log;  // three examples
    EXPECT_EQ(strict_error(path).rfind(path + ": animations: 42 node properties", 0), 0u);
}

// Channels with path "pointer" but no KHR_animation_pointer pointer (the file does not
// use the extension) target nothing. (Debian's tinygltf drops channels without a node
// itself, with its own warning per channel, which the loader counts:
// ParserWarningsAreCountedPerKind; gltf_pointer_channels.cpp restores them for files that
// use the extension.)
TEST(GltfSummaryWarnings, ChannelsWithoutTargetNodeAreOneWarning) {
    const test::ScratchDir dir;
    test::GltfBuilder b;
    b.add<float>({0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3");
    const int in = b.add<float>({0, 1}, test::kFloat, "SCALAR");
    const int out = b.add<float>({0, 0, 0, 1, 1, 1}, test::kFloat, "VEC3");
    const std::string sampler =
        "{\"input\":" + std::to_string(in) + ",\"output\":" + std::to_string(out) + "}";
    const std::string path =
        b.write(dir, "untargeted.gltf",
                test::one_mesh_scene("{\"attributes\":{\"POSITION\":0}}") +
                    ",\"animations\":[{\"samplers\":[" + sampler +
                    "],\"channels\":["
                    "{\"sampler\":0,\"target\":{\"node\":0,\"path\":\"pointer\"}},"
                    "{\"sampler\":0,\"target\":{\"node\":0,\"path\":\"pointer\"}}]}]",
                test::BufferStorage::DataUri);
    const std::string log = warnings_of(path);
    EXPECT_EQ(count(log, "warning: "), 1u) << log;
    EXPECT_NE(log.find(path + ": animations: 2 channel(s) without a target node ignored "
                              "(animations[0].channels[0], animations[0].channels[1])"),
              std::string::npos)
        << log;
}

TEST(GltfSummaryWarnings, ParserWarningsAreCountedPerKind) {
    const test::ScratchDir dir;
    test::GltfBuilder b;
    b.add<float>({0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3");
    const int in = b.add<float>({0, 1}, test::kFloat, "SCALAR");
    const int out = b.add<float>({0, 0, 0, 1, 1, 1}, test::kFloat, "VEC3");
    const std::string sampler =
        "{\"input\":" + std::to_string(in) + ",\"output\":" + std::to_string(out) + "}";
    std::string channels;
    for (int i = 0; i < 5; ++i)
        channels += std::string(i ? "," : "") + "{\"sampler\":0,\"target\":{\"path\":\"scale\"}}";
    const std::string path = b.write(dir, "nodeless.gltf",
                                     test::one_mesh_scene("{\"attributes\":{\"POSITION\":0}}") +
                                         ",\"animations\":[{\"samplers\":[" + sampler +
                                         "],\"channels\":[" + channels + "]}]",
                                     test::BufferStorage::DataUri);
    const std::string log = warnings_of(path);
    EXPECT_EQ(count(log, "warning: "), 2u) << log;  // tinygltf's two lines per channel
    EXPECT_EQ(
        count(log, path + ": `node` field is missing in animation.channels.target (5 times)\n"), 1u)
        << log;
    EXPECT_EQ(count(log, " (5 times)\n"), 2u) << log;
}

// A skinned triangle used by two nodes, with float WEIGHTS_0 summing to 1, 0.8 and 0.9995,
// and a second primitive with normalized unsigned byte weights 255, 127 + 127 and 200:
// all but the two sums of exactly 1 are counted, once although two nodes draw the mesh.
std::string skin_file(const test::ScratchDir& dir) {
    test::GltfBuilder b;
    const int pos = b.add<float>({0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3",
                                 "\"min\":[0,0,0],\"max\":[1,1,0]");
    const int joints = b.add<uint8_t>(std::vector<uint8_t>(12, 0), test::kUByte, "VEC4");
    const int wf =
        b.add<float>({1, 0, 0, 0, 0.5f, 0.3f, 0, 0, 0.9995f, 0, 0, 0}, test::kFloat, "VEC4");
    const int wb = b.add<uint8_t>({255, 0, 0, 0, 127, 127, 0, 0, 200, 0, 0, 0}, test::kUByte,
                                  "VEC4", "\"normalized\":true");
    auto prim = [&](int w) {
        return "{\"attributes\":{\"POSITION\":" + std::to_string(pos) +
               ",\"JOINTS_0\":" + std::to_string(joints) + ",\"WEIGHTS_0\":" + std::to_string(w) +
               "}}";
    };
    return b.write(dir, "weights.gltf",
                   "\"meshes\":[{\"primitives\":[" + prim(wf) + "," + prim(wb) +
                       "]}],\"skins\":[{\"joints\":[2]}],\"nodes\":[{\"mesh\":0,\"skin\":0},"
                       "{\"mesh\":0,\"skin\":0},{}],\"scenes\":[{\"nodes\":[0,1,2]}]",
                   test::BufferStorage::DataUri);
}

TEST(GltfSummaryWarnings, UnnormalizedSkinWeightsAreOneWarningPerFile) {
    const test::ScratchDir dir;
    const std::string path = skin_file(dir);
    const std::string log = warnings_of(path);
    EXPECT_EQ(count(log, "warning: "), 1u) << log;
    EXPECT_NE(log.find(path + ": skins: the skin weights of 4 vertices do not sum to 1, in 1 "
                              "mesh(es) (meshes[0]); first: meshes[0].primitives[0] vertex 1 "
                              "sums to 0.800000; each vertex's weights are scaled to sum to 1"),
              std::string::npos)
        << log;
    EXPECT_EQ(strict_error(path).rfind(path + ": skins: the skin weights of 4 vertices", 0), 0u);
}

// Zero scale hides a subtree (valid glTF): four such nodes, one of them a child of
// another, are one warning naming the three whose subtrees are skipped.
TEST(GltfSummaryWarnings, SingularNodesAreOneWarning) {
    const test::ScratchDir dir;
    test::GltfBuilder b;
    b.add<float>({0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3");
    const std::string zero = "\"mesh\":0,\"scale\":[0,0,0]";
    const std::string path =
        b.write(dir, "hidden.gltf",
                "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],\"nodes\":[{" +
                    zero + ",\"children\":[3]},{" + zero + "},{\"mesh\":0},{" + zero + "},{" +
                    zero + "}],\"scenes\":[{\"nodes\":[0,1,2,4]}]",
                test::BufferStorage::DataUri);
    Scene s;
    testing::internal::CaptureStderr();
    s = load_gltf(path);
    const std::string log = testing::internal::GetCapturedStderr();
    EXPECT_EQ(count(log, "warning: "), 1u) << log;
    EXPECT_NE(log.find(path + ": nodes: 3 node(s) have a singular transform (zero scale?) at a "
                              "time step; their subtrees are skipped (nodes[0], nodes[1], "
                              "nodes[4])\n"),
              std::string::npos)
        << log;
    EXPECT_EQ(s.instances.size(), 1u);
    EXPECT_EQ(strict_error(path).rfind(path + ": nodes: 3 node(s) have a singular", 0), 0u);
}

// A skinned mesh placed by two nodes with EXT_mesh_gpu_instancing: a skinned mesh is in
// world space and the extension gives it no instance transform, so each node draws one
// skinned copy; one warning for both.
TEST(GltfSummaryWarnings, InstancedSkinnedMeshesAreOneWarning) {
    const test::ScratchDir dir;
    test::GltfBuilder b;
    b.add<float>({0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3");
    b.add<uint8_t>(std::vector<uint8_t>(12, 0), test::kUByte, "VEC4");
    b.add<float>({1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, test::kFloat, "VEC4");
    b.add<float>({0, 0, 0, 5, 0, 0}, test::kFloat, "VEC3");
    const std::string instanced =
        "{\"mesh\":0,\"skin\":0,\"extensions\":{\"EXT_mesh_gpu_instancing\":{\"attributes\":"
        "{\"TRANSLATION\":3}}}}";
    const std::string path = b.write(
        dir, "instanced_skin.gltf",
        "\"extensionsUsed\":[\"EXT_mesh_gpu_instancing\"],\"meshes\":[{\"primitives\":[{"
        "\"attributes\":{\"POSITION\":0,\"JOINTS_0\":1,\"WEIGHTS_0\":2}}]}],"
        "\"skins\":[{\"joints\":[2]}],\"nodes\":[" +
            instanced + "," + instanced + ",{}],\"scenes\":[{\"nodes\":[0,1,2]}]",
        test::BufferStorage::DataUri);
    const std::string log = warnings_of(path);
    EXPECT_EQ(count(log, "warning: "), 1u) << log;
    EXPECT_NE(log.find(path + ": nodes: 2 node(s) use EXT_mesh_gpu_instancing on a skinned mesh, "
                              "which has no instance transform: one skinned copy is drawn "
                              "(nodes[0], nodes[1])\n"),
              std::string::npos)
        << log;
    EXPECT_EQ(load_gltf(path).instances.size(), 2u);
}

// A skin whose skeleton root (node 1) and joints (nodes 1 and 2) are in no scene: its pose
// is undefined (NODE_SKIN_NO_SCENE). One warning names the skin and the nodes; the render
// goes on, with the joints posed from their own transforms and parents.
TEST(GltfSummaryWarnings, SkinOutsideTheSceneIsNamed) {
    const test::ScratchDir dir;
    test::GltfBuilder b;
    b.add<float>({0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3");
    b.add<uint8_t>({0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, test::kUByte, "VEC4");
    b.add<float>({1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, test::kFloat, "VEC4");
    const std::string skinned = "{\"mesh\":0,\"skin\":0}";
    const std::string path = b.write(
        dir, "skin_no_scene.gltf",
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"JOINTS_0\":1,"
        "\"WEIGHTS_0\":2}}]}],\"skins\":[{\"name\":\"rig\",\"skeleton\":1,\"joints\":[1,2]}],"
        "\"nodes\":[" + skinned + ",{\"name\":\"hips\",\"translation\":[0,3,0],"
        "\"children\":[2]},{\"translation\":[0,0,1]}," + skinned + "],"
        "\"scenes\":[{\"nodes\":[0,3]}]",
        test::BufferStorage::DataUri);
    Scene s;
    testing::internal::CaptureStderr();
    s = load_gltf(path);
    const std::string log = testing::internal::GetCapturedStderr();
    EXPECT_EQ(count(log, "warning: "), 1u) << log;
    EXPECT_NE(log.find(path + ": skins: 1 skin(s) drawn in scenes[0] have nodes outside it, so "
                              "their pose is undefined (skins[0] 'rig': its skeleton root "
                              "nodes[1] 'hips' and 2 of its 2 joints (nodes[1] 'hips', "
                              "nodes[2])); those nodes are posed from their own transforms "
                              "and parents\n"),
              std::string::npos)
        << log;
    ASSERT_EQ(s.instances.size(), 2u);
    const TriangleMesh& m = s.meshes[s.objects[s.instances[0].object].meshes.at(0)];
    EXPECT_EQ(m.positions[0], Vec3(0, 3, 0));  // joint 0: the root at y = 3
    EXPECT_EQ(m.positions[1], Vec3(1, 3, 1));  // joint 1: its child, 1 further in z
    EXPECT_EQ(strict_error(path).rfind(path + ": skins: 1 skin(s) drawn in scenes[0]", 0), 0u);
}

// A joint under a zero-scaled node is in the scene (hidden, not outside it): only the
// zero scale is reported.
TEST(GltfSummaryWarnings, SkinJointUnderAZeroScaleIsInTheScene) {
    const test::ScratchDir dir;
    test::GltfBuilder b;
    b.add<float>({0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3");
    b.add<uint8_t>(std::vector<uint8_t>(12, 0), test::kUByte, "VEC4");
    b.add<float>({1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, test::kFloat, "VEC4");
    const std::string path = b.write(
        dir, "skin_hidden_joint.gltf",
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"JOINTS_0\":1,"
        "\"WEIGHTS_0\":2}}]}],\"skins\":[{\"joints\":[2]}],\"nodes\":[{\"mesh\":0,"
        "\"skin\":0},{\"scale\":[0,0,0],\"children\":[2]},{}],\"scenes\":[{\"nodes\":[0,1]}]",
        test::BufferStorage::DataUri);
    const std::string log = warnings_of(path);
    EXPECT_EQ(count(log, "warning: "), 1u) << log;
    EXPECT_NE(log.find(": nodes: 1 node(s) have a singular transform"), std::string::npos) << log;
}

}  // namespace
}  // namespace penumbra
