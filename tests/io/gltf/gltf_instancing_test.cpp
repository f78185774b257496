// EXT_mesh_gpu_instancing: per-instance TRS attributes become Instances of one Object.
#include "io/gltf/gltf_instancing.h"

#include <gtest/gtest.h>

#include "core/accel/embree_accel.h"
#include "core/error.h"
#include "io/gltf/gltf_loader.h"
#include "support/gltf_builder.h"
#include "support/paths.h"

namespace penumbra {
namespace {

// One triangle, instanced three times by a node that is itself translated by +10 Y.
std::string instanced_file(const test::ScratchDir& dir, const std::string& name,
                           const std::vector<float>& translations,
                           const std::vector<float>& scales) {
    test::GltfBuilder b;
    const int pos = b.add<float>({0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3",
                                 "\"min\":[0,0,0],\"max\":[1,1,0]");
    const int t = b.add<float>(translations, test::kFloat, "VEC3");
    const int s = b.add<float>(scales, test::kFloat, "VEC3");
    const std::string members =
        "\"extensionsUsed\":[\"EXT_mesh_gpu_instancing\"],"
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(pos) +
        "}}]}],\"nodes\":[{\"mesh\":0,\"translation\":[0,10,0],\"extensions\":{"
        "\"EXT_mesh_gpu_instancing\":{\"attributes\":{\"TRANSLATION\":" + std::to_string(t) +
        ",\"SCALE\":" + std::to_string(s) + "}}}}],\"scenes\":[{\"nodes\":[0]}]";
    return b.write(dir, name, members, test::BufferStorage::Glb);
}

TEST(GltfInstancing, EachInstanceGetsItsTransformTimesTheNodes) {
    const test::ScratchDir dir;
    const std::string path = instanced_file(dir, "i.glb", {0, 0, 0, 5, 0, 0, 0, 0, -5},
                                            {1, 1, 1, 2, 2, 2, -1, 1, 1});
    const Scene s = load_gltf(path);
    ASSERT_EQ(s.objects.size(), 1u);
    ASSERT_EQ(s.instances.size(), 3u);
    const Vec3 v(1, 0, 0);
    const Vec3 expected[] = {{1, 10, 0}, {7, 10, 0}, {-1, 10, -5}};
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(s.instances[i].object, 0u);
        const Vec3 p = s.instances[i].to_world.point(v);
        EXPECT_NEAR(p.x, expected[i].x, 1e-5f);
        EXPECT_NEAR(p.y, expected[i].y, 1e-5f);
        EXPECT_NEAR(p.z, expected[i].z, 1e-5f);
    }
    EXPECT_TRUE(s.instances[2].to_world.swaps_handedness());
    // Embree builds the triangle once and hits every instance (with two levels: else
    // so small an object is flattened, core/accel/embree_accel.h).
    EmbreeBuildOptions two_levels;
    two_levels.flatten = false;
    const EmbreeAccel accel(s, two_levels);
    EXPECT_EQ(accel.stats().object_scenes, 1u);
    for (int i = 0; i < 3; ++i) {
        Ray r;
        r.o = s.instances[i].to_world.point({0.2f, 0.2f, 0}) + Vec3(0, 0, 3);
        r.d = {0, 0, -1};
        const auto hit = accel.intersect(r);
        ASSERT_TRUE(hit) << i;
        EXPECT_EQ(hit->instance, uint32_t(i));
    }
}

TEST(GltfInstancing, MismatchedAttributeCountsAreAnError) {
    const test::ScratchDir dir;
    const std::string path =
        instanced_file(dir, "bad.glb", {0, 0, 0, 5, 0, 0}, {1, 1, 1, 2, 2, 2, 3, 3, 3});
    try {
        load_gltf(path);
        FAIL() << "expected a SceneError";
    } catch (const SceneError& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("bad.glb: nodes[0].extensions.EXT_mesh_gpu_instancing"),
                  std::string::npos) << msg;
        EXPECT_NE(msg.find("SCALE accessor has 3 elements, another attribute has 2"),
                  std::string::npos) << msg;
    }
}

TEST(GltfInstancing, BundledSceneHasMirroredAndNonUniformInstances) {
    const Scene s = load_gltf(test::source_path("scenes/instances.gltf"));
    ASSERT_EQ(s.objects.size(), 1u);
    ASSERT_EQ(s.instances.size(), 400u);
    int mirrored = 0;
    for (const Instance& inst : s.instances) mirrored += inst.to_world.swaps_handedness();
    EXPECT_EQ(mirrored, 36);  // every 11th from 5 (make_instances.py)
}

}  // namespace
}  // namespace penumbra
