// Deformation at load: morph targets (mesh, node and animated weights) and skins (joints
// times inverse bind matrices, the mesh node's transform ignored), at a still time and as
// time steps over the shutter; undeformed meshes stay shared.
#include <gtest/gtest.h>

#include "core/error.h"
#include "io/gltf/gltf_loader.h"
#include "support/gltf_builder.h"

namespace penumbra {
namespace {

void expect_near(Vec3 a, Vec3 b, const std::string& what) {
    EXPECT_NEAR(a.x, b.x, 1e-5f) << what;
    EXPECT_NEAR(a.y, b.y, 1e-5f) << what;
    EXPECT_NEAR(a.z, b.z, 1e-5f) << what;
}

Scene load_at(const std::string& path, double open, double close) {
    GltfLoadOptions o;
    o.shutter_open = open;
    o.shutter_close = close;
    return load_gltf(path, o);
}

// A triangle with one morph target moving every vertex +1 in z (and tilting normals).
// Node 0: default weights (mesh.weights = [0.5]); node 1: node.weights = [0.25]; node 2:
// weights animated LINEAR 0 -> 1 over [0, 1] s. `mesh_weights` false: no mesh.weights.
std::string morph_file(const test::ScratchDir& dir, bool mesh_weights) {
    test::GltfBuilder b;
    const int pos = b.add<float>({0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3",
                                 "\"min\":[0,0,0],\"max\":[1,1,0]");
    const int nrm = b.add<float>({0, 0, 1, 0, 0, 1, 0, 0, 1}, test::kFloat, "VEC3");
    const int dp = b.add<float>({0, 0, 1, 0, 0, 1, 0, 0, 1}, test::kFloat, "VEC3",
                                "\"min\":[0,0,1],\"max\":[0,0,1]");
    const int dn = b.add<float>({1, 0, 0, 1, 0, 0, 1, 0, 0}, test::kFloat, "VEC3");
    const int in = b.add<float>({0, 1}, test::kFloat, "SCALAR");
    const int out = b.add<float>({0, 1}, test::kFloat, "SCALAR");
    const std::string members =
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(pos) +
        ",\"NORMAL\":" + std::to_string(nrm) + "},\"targets\":[{\"POSITION\":" +
        std::to_string(dp) + ",\"NORMAL\":" + std::to_string(dn) + "}]}]" +
        (mesh_weights ? ",\"weights\":[0.5]" : "") +
        "}],\"nodes\":[{\"mesh\":0},{\"mesh\":0,\"weights\":[0.25]},{\"mesh\":0}],"
        "\"scenes\":[{\"nodes\":[0,1,2]}],\"animations\":[{\"samplers\":[{\"input\":" +
        std::to_string(in) + ",\"output\":" + std::to_string(out) +
        "}],\"channels\":[{\"sampler\":0,\"target\":{\"node\":2,\"path\":\"weights\"}}]}]";
    return b.write(dir, "morph.gltf", members, test::BufferStorage::DataUri);
}

const TriangleMesh& mesh_of(const Scene& s, size_t instance) {
    const Object& o = s.objects[s.instances[instance].object];
    return s.meshes[o.meshes.at(0)];
}

TEST(GltfDeform, MorphWeightsFromMeshNodeAndAnimation) {
    const test::ScratchDir dir;
    const Scene s = load_at(morph_file(dir, true), 0.5, 0.5);
    ASSERT_EQ(s.instances.size(), 3u);
    const float expected_z[] = {0.5f, 0.25f, 0.5f};  // mesh, node, animated at 0.5 s
    for (size_t i = 0; i < 3; ++i) {
        const TriangleMesh& m = mesh_of(s, i);
        EXPECT_TRUE(m.motion_positions.empty()) << "a still";
        expect_near(m.positions[1], {1, 0, expected_z[i]}, "instance " + std::to_string(i));
        // Normal (0,0,1) + w (1,0,0), renormalized.
        expect_near(m.normals[1], normalize(Vec3(expected_z[i], 0, 1)),
                    "normal " + std::to_string(i));
        EXPECT_EQ(m.bounds.hi.z, expected_z[i]);
        EXPECT_NE(s.instances[i].object, 0u) << "a per-node copy";
    }
    // The file's own mesh keeps its base shape.
    EXPECT_EQ(s.meshes[0].positions[1].z, 0);
}

TEST(GltfDeform, AnimatedWeightsGiveDeformationSteps) {
    const test::ScratchDir dir;
    const Scene s = load_at(morph_file(dir, false), 0.25, 0.75);
    // Without mesh.weights node 0 is undeformed: it shares object 0, and only node 2's
    // weights move within the shutter.
    EXPECT_EQ(s.instances[0].object, 0u);
    EXPECT_TRUE(mesh_of(s, 1).motion_positions.empty());
    const TriangleMesh& m = mesh_of(s, 2);
    ASSERT_EQ(m.motion_positions.size(), 2u);
    ASSERT_EQ(m.motion_normals.size(), 2u);
    expect_near(m.motion_positions[0][2], {0, 1, 0.25f}, "open");
    expect_near(m.motion_positions[1][2], {0, 1, 0.75f}, "close");
    EXPECT_EQ(m.positions, m.motion_positions[0]);
    EXPECT_NEAR(m.bounds.lo.z, 0.25f, 1e-6f);
    EXPECT_NEAR(m.bounds.hi.z, 0.75f, 1e-6f);
    EXPECT_TRUE(s.instances[2].motion.empty()) << "the node itself does not move";
}

// A skinned triangle: vertex 0 bound to joint 0 (node 1, static), vertex 1 to joint 1
// (node 2, bind pose at z = 2, animated to z = 4 over [0, 1] s), vertex 2 half to each.
// The mesh node 0 sits at x = 100, which skinning ignores.
std::string skin_file(const test::ScratchDir& dir, int bad_joint = -1) {
    test::GltfBuilder b;
    const int pos = b.add<float>({0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3",
                                 "\"min\":[0,0,0],\"max\":[1,1,0]");
    const uint8_t j1 = bad_joint >= 0 ? uint8_t(bad_joint) : 1;
    const int joints = b.add<uint8_t>({0, 0, 0, 0, j1, 0, 0, 0, 0, 1, 0, 0}, test::kUByte, "VEC4");
    const int weights = b.add<float>({1, 0, 0, 0, 1, 0, 0, 0, 0.5f, 0.5f, 0, 0}, test::kFloat,
                                     "VEC4");
    // Column-major inverse bind matrices: identity, and a translation by (0, 0, -2).
    const int ibm = b.add<float>({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1,  //
                                  1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -2, 1},
                                 test::kFloat, "MAT4");
    const int in = b.add<float>({0, 1}, test::kFloat, "SCALAR");
    const int out = b.add<float>({0, 0, 2, 0, 0, 4}, test::kFloat, "VEC3");
    const std::string members =
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(pos) +
        ",\"JOINTS_0\":" + std::to_string(joints) + ",\"WEIGHTS_0\":" + std::to_string(weights) +
        "}}]}],\"skins\":[{\"joints\":[1,2],\"inverseBindMatrices\":" + std::to_string(ibm) +
        "}],\"nodes\":[{\"mesh\":0,\"skin\":0,\"translation\":[100,0,0]},{\"children\":[2]},"
        "{\"translation\":[0,0,2]}],\"scenes\":[{\"nodes\":[0,1]}],"
        "\"animations\":[{\"samplers\":[{\"input\":" + std::to_string(in) + ",\"output\":" +
        std::to_string(out) +
        "}],\"channels\":[{\"sampler\":0,\"target\":{\"node\":2,\"path\":\"translation\"}}]}]";
    return b.write(dir, "skin.gltf", members, test::BufferStorage::DataUri);
}

TEST(GltfDeform, SkinInBindPoseIsTheMeshInWorldSpace) {
    const test::ScratchDir dir;
    const Scene s = load_gltf(skin_file(dir));
    ASSERT_EQ(s.instances.size(), 1u);
    EXPECT_TRUE(s.instances[0].to_world.matrix().is_identity()) << "node transform ignored";
    const TriangleMesh& m = mesh_of(s, 0);
    EXPECT_TRUE(m.motion_positions.empty());
    // Flat-shaded (no NORMAL): per-triangle vertices in file order 0, 1, 2.
    expect_near(m.positions[0], {0, 0, 0}, "v0");
    expect_near(m.positions[1], {1, 0, 0}, "v1");
    expect_near(m.positions[2], {0, 1, 0}, "v2");
}

TEST(GltfDeform, SkinFollowsItsJointsOverTheShutter) {
    const test::ScratchDir dir;
    // Still at 0.5 s: joint 1 at z = 3, one above its bind pose.
    Scene s = load_at(skin_file(dir), 0.5, 0.5);
    const TriangleMesh& still = mesh_of(s, 0);
    expect_near(still.positions[1], {1, 0, 1}, "v1 at 0.5 s");
    expect_near(still.positions[2], {0, 1, 0.5f}, "v2 at 0.5 s (half weight)");
    // The face normal follows the deformed triangle.
    expect_near(still.normals[0],
                normalize(cross(Vec3(1, 0, 1), Vec3(0, 1, 0.5f))), "flat normal");

    s = load_at(skin_file(dir), 0, 1);
    const TriangleMesh& m = mesh_of(s, 0);
    ASSERT_EQ(m.motion_positions.size(), 2u);
    expect_near(m.motion_positions[0][1], {1, 0, 0}, "v1 open");
    expect_near(m.motion_positions[1][1], {1, 0, 2}, "v1 close");
    expect_near(m.motion_positions[1][2], {0, 1, 1}, "v2 close");
    expect_near(m.motion_positions[1][0], {0, 0, 0}, "v0 bound to the static joint");
    EXPECT_TRUE(s.instances[0].motion.empty());
}

TEST(GltfDeform, JointIndexOutOfRangeIsAnError) {
    const test::ScratchDir dir;
    try {
        load_gltf(skin_file(dir, 7));
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find(
                      "meshes[0].primitives[0]: JOINTS_0 element 1 names joint 7 of a skin with "
                      "2 joints"),
                  std::string::npos)
            << e.what();
    }
}

// Joints outside the scene tree whose parents form a cycle: an error, not a hang.
TEST(GltfDeform, JointInAParentCycleIsAnError) {
    const test::ScratchDir dir;
    test::GltfBuilder b;
    const int pos = b.add<float>({0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3",
                                 "\"min\":[0,0,0],\"max\":[1,1,0]");
    const int joints = b.add<uint8_t>(std::vector<uint8_t>(12, 0), test::kUByte, "VEC4");
    const int weights = b.add<float>({1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, test::kFloat, "VEC4");
    const std::string path = b.write(
        dir, "cycle.gltf",
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(pos) +
            ",\"JOINTS_0\":" + std::to_string(joints) + ",\"WEIGHTS_0\":" +
            std::to_string(weights) +
            "}}]}],\"skins\":[{\"joints\":[1]}],\"nodes\":[{\"mesh\":0,\"skin\":0},"
            "{\"children\":[2]},{\"children\":[1]}],\"scenes\":[{\"nodes\":[0]}]",
        test::BufferStorage::DataUri);
    try {
        load_gltf(path);
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("is its own ancestor (a node cycle)"),
                  std::string::npos)
            << e.what();
    }
}

// Morph targets with a skin, several nodes drawing one skinned mesh, and animated parents.
// Joint 0 is node 1 (scale 2), child of node 4, which moves from y = 0 to y = 10 over
// [0, 1] s; no inverse bind matrices (identity). One morph target moves every vertex +1
// in x. Node 0 (mesh.weights 0.5, its own translation x = 100) and node 3
// (node.weights 1) draw the mesh, both under node 2, which moves from x = 0 to x = 10:
// a skinned mesh ignores its node's transform and motion (glTF 2.0, 3.7.3.3).
std::string morph_skin_file(const test::ScratchDir& dir) {
    test::GltfBuilder b;
    const int pos = b.add<float>({0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3");
    const int dp = b.add<float>({1, 0, 0, 1, 0, 0, 1, 0, 0}, test::kFloat, "VEC3");
    const int joints = b.add<uint8_t>(std::vector<uint8_t>(12, 0), test::kUByte, "VEC4");
    const int weights = b.add<float>({1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, test::kFloat, "VEC4");
    const int in = b.add<float>({0, 1}, test::kFloat, "SCALAR");
    const int along_x = b.add<float>({0, 0, 0, 10, 0, 0}, test::kFloat, "VEC3");
    const int along_y = b.add<float>({0, 0, 0, 0, 10, 0}, test::kFloat, "VEC3");
    auto sampler = [&](int out) {
        return "{\"input\":" + std::to_string(in) + ",\"output\":" + std::to_string(out) + "}";
    };
    return b.write(
        dir, "morph_skin.gltf",
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(pos) +
            ",\"JOINTS_0\":" + std::to_string(joints) + ",\"WEIGHTS_0\":" +
            std::to_string(weights) + "},\"targets\":[{\"POSITION\":" + std::to_string(dp) +
            "}]}],\"weights\":[0.5]}],\"skins\":[{\"joints\":[1]}],\"nodes\":["
            "{\"mesh\":0,\"skin\":0,\"translation\":[100,0,0]},{\"scale\":[2,2,2]},"
            "{\"children\":[0,3]},{\"mesh\":0,\"skin\":0,\"weights\":[1]},{\"children\":[1]}],"
            "\"scenes\":[{\"nodes\":[2,4]}],\"animations\":[{\"samplers\":[" +
            sampler(along_x) + "," + sampler(along_y) +
            "],\"channels\":[{\"sampler\":0,\"target\":{\"node\":2,\"path\":\"translation\"}},"
            "{\"sampler\":1,\"target\":{\"node\":4,\"path\":\"translation\"}}]}]",
        test::BufferStorage::DataUri);
}

// Morph first, then skin: vertex 1 (1, 0, 0) morphed by 0.5 is (1.5, 0, 0), scaled by the
// joint to (3, 0, 0), lifted by the joint's parent to y = 5 at 0.5 s. Skinning first would
// give (2.5, 5, 0).
TEST(GltfDeform, MorphBeforeSkinPerNodeUnderAnimatedParents) {
    const test::ScratchDir dir;
    const std::string path = morph_skin_file(dir);
    Scene s = load_at(path, 0.5, 0.5);
    ASSERT_EQ(s.instances.size(), 2u);
    EXPECT_NE(s.instances[0].object, s.instances[1].object) << "a copy per node";
    for (const Instance& inst : s.instances) {
        EXPECT_TRUE(inst.to_world.matrix().is_identity()) << inst.name;
        EXPECT_TRUE(inst.motion.empty()) << inst.name;
    }
    expect_near(mesh_of(s, 0).positions[1], {3, 5, 0}, "node 0, vertex 1");
    expect_near(mesh_of(s, 0).positions[0], {1, 5, 0}, "node 0, vertex 0");
    expect_near(mesh_of(s, 1).positions[1], {4, 5, 0}, "node 3 (weight 1), vertex 1");

    // Over the shutter the joint's parent moves the skin; the mesh nodes' parent does not.
    s = load_at(path, 0, 1);
    const TriangleMesh& m = mesh_of(s, 0);
    ASSERT_EQ(m.motion_positions.size(), 2u);
    expect_near(m.motion_positions[0][1], {3, 0, 0}, "open");
    expect_near(m.motion_positions[1][1], {3, 10, 0}, "close");
    EXPECT_TRUE(s.instances[0].motion.empty());
}

// EXT_mesh_gpu_instancing on a morphed mesh: every instance draws the morphed copy, at
// node world x instance transform (the extension's WorldPosition = NodeWorld x Instance x
// vertex, the vertex morphed).
TEST(GltfDeform, GpuInstancesOfAMorphedMeshDrawTheMorphedCopy) {
    const test::ScratchDir dir;
    test::GltfBuilder b;
    b.add<float>({0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3");
    b.add<float>({0, 0, 1, 0, 0, 1, 0, 0, 1}, test::kFloat, "VEC3");
    b.add<float>({0, 0, 0, 5, 0, 0}, test::kFloat, "VEC3");
    const std::string path = b.write(
        dir, "instanced_morph.gltf",
        "\"extensionsUsed\":[\"EXT_mesh_gpu_instancing\"],\"meshes\":[{\"primitives\":[{"
        "\"attributes\":{\"POSITION\":0},\"targets\":[{\"POSITION\":1}]}],\"weights\":[1]}],"
        "\"nodes\":[{\"mesh\":0,\"translation\":[0,1,0],\"extensions\":{"
        "\"EXT_mesh_gpu_instancing\":{\"attributes\":{\"TRANSLATION\":2}}}}],"
        "\"scenes\":[{\"nodes\":[0]}]",
        test::BufferStorage::DataUri);
    testing::internal::CaptureStderr();
    const Scene s = load_gltf(path);
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
    ASSERT_EQ(s.instances.size(), 2u);
    EXPECT_NE(s.instances[0].object, 0u) << "the morphed copy, not the file's mesh";
    EXPECT_EQ(s.instances[0].object, s.instances[1].object);
    expect_near(mesh_of(s, 0).positions[1], {1, 0, 1}, "morphed vertex");
    expect_near(s.instances[0].to_world.point({0, 0, 0}), {0, 1, 0}, "instance 0");
    expect_near(s.instances[1].to_world.point({0, 0, 0}), {5, 1, 0}, "instance 1");
}

}  // namespace
}  // namespace penumbra
