// A file loaded once and posed at several shutters: each pose is the scene that loading the
// file at that shutter gives, bit for bit, while the file is parsed and its images decoded
// once; a file whose materials are animated reads its materials again at each pose. Which
// poses keep their mesh arrays in place for an accelerator to serve the next pose.
#include "io/gltf/gltf_asset.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "support/animated_scene.h"
#include "support/paths.h"

namespace penumbra {
namespace {

const std::string kFox = test::shared_path("scenes/wild/Fox/Fox.glb");  // skinned, textured
const std::string kBoxAnimated = test::shared_path("scenes/khronos/BoxAnimated.gltf");  // rigid

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}
bool same_bits(const Mat4& a, const Mat4& b) { return std::memcmp(&a, &b, sizeof(Mat4)) == 0; }

// What a pose decides: the meshes (deformed ones appended), instances, cameras, lights,
// materials and images.
void expect_same_scene(const Scene& a, const Scene& b, const std::string& what) {
    ASSERT_EQ(a.meshes.size(), b.meshes.size()) << what;
    for (size_t i = 0; i < a.meshes.size(); ++i) {
        const TriangleMesh &ma = a.meshes[i], &mb = b.meshes[i];
        EXPECT_TRUE(same_bits(ma.positions, mb.positions)) << what << ": mesh " << i;
        EXPECT_TRUE(same_bits(ma.normals, mb.normals)) << what << ": mesh " << i;
        EXPECT_TRUE(same_bits(ma.indices, mb.indices)) << what << ": mesh " << i;
        EXPECT_EQ(ma.material, mb.material) << what << ": mesh " << i;
        ASSERT_EQ(ma.motion_positions.size(), mb.motion_positions.size()) << what;
        for (size_t k = 0; k < ma.motion_positions.size(); ++k)
            EXPECT_TRUE(same_bits(ma.motion_positions[k], mb.motion_positions[k])) << what;
    }
    ASSERT_EQ(a.objects.size(), b.objects.size()) << what;
    for (size_t i = 0; i < a.objects.size(); ++i)
        EXPECT_EQ(a.objects[i].meshes, b.objects[i].meshes) << what << ": object " << i;
    ASSERT_EQ(a.instances.size(), b.instances.size()) << what;
    for (size_t i = 0; i < a.instances.size(); ++i) {
        const Instance &ia = a.instances[i], &ib = b.instances[i];
        EXPECT_EQ(ia.object, ib.object) << what << ": instance " << i;
        EXPECT_TRUE(same_bits(ia.to_world.matrix(), ib.to_world.matrix())) << what;
        ASSERT_EQ(ia.motion.size(), ib.motion.size()) << what;
        for (size_t k = 0; k < ia.motion.size(); ++k)
            EXPECT_TRUE(same_bits(ia.motion[k].matrix(), ib.motion[k].matrix())) << what;
        EXPECT_EQ(ia.visibility.at_open, ib.visibility.at_open) << what;
        EXPECT_EQ(ia.visibility.flips, ib.visibility.flips) << what;
    }
    EXPECT_EQ(a.cameras.size(), b.cameras.size()) << what;
    EXPECT_EQ(a.lights.size(), b.lights.size()) << what;
    ASSERT_EQ(a.materials.size(), b.materials.size()) << what;
    for (size_t i = 0; i < a.materials.size(); ++i) {
        EXPECT_TRUE(same_bits(std::vector<Vec4>{a.materials[i].base_color},
                              std::vector<Vec4>{b.materials[i].base_color}))
            << what << ": material " << i;
    }
    EXPECT_EQ(a.material_steps, b.material_steps) << what;
    EXPECT_EQ(a.hidden_material, b.hidden_material) << what;
    EXPECT_EQ(a.timed_materials, b.timed_materials) << what;
    ASSERT_EQ(a.images.size(), b.images.size()) << what;
    for (size_t i = 0; i < a.images.size(); ++i)
        EXPECT_EQ(a.images[i].bytes(), b.images[i].bytes()) << what << ": image " << i;
    EXPECT_EQ(a.textures.size(), b.textures.size()) << what;
    EXPECT_EQ(a.shutter_open, b.shutter_open) << what;
    EXPECT_EQ(a.shutter_close, b.shutter_close) << what;
}

Scene load_at(const std::string& path, double open, double close) {
    GltfLoadOptions o;
    o.shutter_open = open;
    o.shutter_close = close;
    return load_gltf(path, o);
}

// Frames 0.1 s apart, each open for half of that: stills and motion steps both.
void expect_poses_match_loads(const std::string& path, GltfAsset& asset, bool recycle) {
    for (int f = 0; f < 3; ++f) {
        const double open = 0.1 * f, close = open + (f == 1 ? 0.05 : 0.0);
        Scene posed = asset.scene_at(open, close);
        expect_same_scene(posed, load_at(path, open, close), path + " frame " + std::to_string(f));
        if (recycle) asset.recycle(std::move(posed));
    }
}

TEST(GltfAsset, PosesEqualLoadsWithOneParseAndOneImageDecode) {
    for (const std::string& path : {kFox, kBoxAnimated}) {
        GltfAsset asset(path, {});
        expect_poses_match_loads(path, asset, true);
        EXPECT_EQ(asset.parses(), 1u) << path;
        EXPECT_EQ(asset.static_builds(), 1u) << path;
    }
}

// A scene not handed back leaves nothing to reuse: the next pose reads the file again
// (its encoded images were dropped once decoded) and is still the same scene.
TEST(GltfAsset, PosesWithoutRecyclingReadTheFileAgain) {
    GltfAsset asset(kFox, {});
    expect_poses_match_loads(kFox, asset, false);
    EXPECT_EQ(asset.parses(), 3u);
    EXPECT_EQ(asset.static_builds(), 3u);
}

// Materials animated through KHR_animation_pointer take their values at each shutter:
// they are read again for every pose, from the one parse.
TEST(GltfAsset, AnimatedMaterialsAreReadAtEveryPose) {
    const test::ScratchDir dir;
    const std::string path = test::animated_scene(dir);
    GltfAsset asset(path, {});
    expect_poses_match_loads(path, asset, true);
    EXPECT_EQ(asset.parses(), 1u);
    EXPECT_EQ(asset.static_builds(), 3u);
}

// The shared meshes stay where they are from pose to pose, unless something deforms (its
// meshes are the pose's own) or the materials are read again (and the meshes with them).
TEST(GltfAsset, KeepsGeometryOnlyWhereNothingDeformsAndTheSharedPartsStay) {
    GltfAsset rigid(kBoxAnimated, {});
    Scene a = rigid.scene_at(0.1, 0.1);
    EXPECT_TRUE(rigid.keeps_geometry(a));
    const Vec3* first = a.meshes.at(0).positions.data();
    rigid.recycle(std::move(a));
    const Scene b = rigid.scene_at(0.2, 0.2);
    EXPECT_EQ(b.meshes.at(0).positions.data(), first);

    GltfAsset skinned(kFox, {});
    EXPECT_FALSE(skinned.keeps_geometry(skinned.scene_at(0.1, 0.1)));

    const test::ScratchDir dir;
    GltfAsset animated(test::animated_scene(dir), {});
    EXPECT_FALSE(animated.keeps_geometry(animated.scene_at(0.1, 0.1)));
}

}  // namespace
}  // namespace penumbra
