// The scene one frame before and after, for motion vectors (Scene::frame_neighbours):
// instances, morphed vertices and cameras posed at the neighbouring times by the same
// animation evaluation as the frame; nothing of it (not even a deformed copy) without
// the option.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "core/error.h"
#include "io/gltf/gltf_loader.h"
#include "support/gltf_builder.h"

namespace penumbra {
namespace {

// Node 0: a triangle with one morph target (+1 in z) whose weight is 0 at 0 and 1 s and 1
// at 2 s (LINEAR); node 1: the same mesh translated LINEARly from x = 0 at 0 s to x = 2 at
// 2 s; node 2: a camera rising LINEARly from (0, 0, 5) at 0 s to (0, 2, 5) at 2 s.
std::string neighbours_file(const test::ScratchDir& dir) {
    test::GltfBuilder b;
    const int pos = b.add<float>({0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3");
    const int dp = b.add<float>({0, 0, 1, 0, 0, 1, 0, 0, 1}, test::kFloat, "VEC3");
    const int t3 = b.add<float>({0, 1, 2}, test::kFloat, "SCALAR");
    const int w = b.add<float>({0, 0, 1}, test::kFloat, "SCALAR");
    const int t2 = b.add<float>({0, 2}, test::kFloat, "SCALAR");
    const int move = b.add<float>({0, 0, 0, 2, 0, 0}, test::kFloat, "VEC3");
    const int rise = b.add<float>({0, 0, 5, 0, 2, 5}, test::kFloat, "VEC3");
    auto sampler = [](int in, int out) {
        return "{\"input\":" + std::to_string(in) + ",\"output\":" + std::to_string(out) + "}";
    };
    const std::string members =
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(pos) +
        "},\"targets\":[{\"POSITION\":" + std::to_string(dp) +
        "}]}]}],"
        "\"cameras\":[{\"type\":\"perspective\",\"perspective\":{\"yfov\":0.8,\"znear\":0.1}}],"
        "\"nodes\":[{\"mesh\":0},{\"mesh\":0},{\"camera\":0,\"translation\":[0,0,5]}],"
        "\"scenes\":[{\"nodes\":[0,1,2]}],\"animations\":[{\"samplers\":[" +
        sampler(t3, w) + "," + sampler(t2, move) + "," + sampler(t2, rise) +
        "],\"channels\":[{\"sampler\":0,\"target\":{\"node\":0,\"path\":\"weights\"}},"
        "{\"sampler\":1,\"target\":{\"node\":1,\"path\":\"translation\"}},"
        "{\"sampler\":2,\"target\":{\"node\":2,\"path\":\"translation\"}}]}]";
    return b.write(dir, "neighbours.gltf", members, test::BufferStorage::DataUri);
}

Scene load_at(const std::string& path, double time, double offset) {
    GltfLoadOptions o;
    o.shutter_open = o.shutter_close = time;
    o.neighbour_frame_offset = offset;
    return load_gltf(path, o);
}

TEST(GltfFrameNeighbours, PoseInstancesVerticesAndCamerasAFrameAway) {
    const test::ScratchDir dir;
    const Scene s = load_at(neighbours_file(dir), 1.0, 0.5);
    ASSERT_TRUE(s.frame_neighbours);
    const NeighbourFrame &prev = s.frame_neighbours->previous, &next = s.frame_neighbours->next;
    EXPECT_EQ(prev.time, 0.5);
    EXPECT_EQ(next.time, 1.5);
    ASSERT_EQ(s.instances.size(), 2u);
    ASSERT_EQ(prev.instances.size(), 2u);
    ASSERT_EQ(next.instances.size(), 2u);
    // Node 1 moves 1 unit a second: x = 1 at the frame, 0.5 and 1.5 around it.
    EXPECT_FLOAT_EQ(s.instances[1].to_world.matrix()(0, 3), 1.0f);
    EXPECT_FLOAT_EQ(prev.instances[1](0, 3), 0.5f);
    EXPECT_FLOAT_EQ(next.instances[1](0, 3), 1.5f);
    // Node 0 rests (weight 0) at the frame and before it, so its own copy's vertices are
    // the frame's then (an empty list); after it the weight is 0.5.
    const uint32_t morphed = s.objects[s.instances[0].object].meshes.at(0);
    EXPECT_NE(s.instances[0].object, 0u) << "a copy, for the frames around";
    ASSERT_GT(next.positions.size(), morphed);
    EXPECT_EQ(s.meshes[morphed].positions[1].z, 0.0f);
    EXPECT_TRUE(prev.positions.size() <= morphed || prev.positions[morphed].empty());
    ASSERT_EQ(next.positions[morphed].size(), 3u);
    EXPECT_FLOAT_EQ(next.positions[morphed][1].z, 0.5f);
    EXPECT_FLOAT_EQ(next.positions[morphed][1].x, 1.0f);
    // The shared, undeformed mesh keeps its own vertices at every frame.
    EXPECT_TRUE(next.positions[0].empty());
    // The camera rises 1 unit a second.
    ASSERT_EQ(prev.cameras.size(), 1u);
    ASSERT_EQ(next.cameras.size(), 1u);
    EXPECT_FLOAT_EQ(s.cameras[0].to_world.matrix()(1, 3), 1.0f);
    EXPECT_FLOAT_EQ(prev.cameras[0].to_world.matrix()(1, 3), 0.5f);
    EXPECT_FLOAT_EQ(next.cameras[0].to_world.matrix()(1, 3), 1.5f);
    EXPECT_FLOAT_EQ(next.cameras[0].yfov, 0.8f);
}

TEST(GltfFrameNeighbours, AStillFileKeepsNothingOfThem) {
    const test::ScratchDir dir;
    test::GltfBuilder b;
    const int pos = b.add<float>({0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3");
    const std::string still = b.write(
        dir, "still.gltf",
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(pos) +
            "}}]}],\"nodes\":[{\"mesh\":0,\"translation\":[1,2,3]}],\"scenes\":[{\"nodes\":[0]}]",
        test::BufferStorage::DataUri);
    const Scene s = load_at(still, 0, 1.0 / 24);
    ASSERT_TRUE(s.frame_neighbours);
    for (const NeighbourFrame* f : {&s.frame_neighbours->previous, &s.frame_neighbours->next}) {
        EXPECT_TRUE(f->instances.empty()) << "every instance stays at its to_world";
        EXPECT_TRUE(f->positions.empty()) << "no mesh deforms";
    }
}

TEST(GltfFrameNeighbours, GpuInstancesFollowTheirAnimatedNode) {
    // A node scaled by 2 and turning LINEARly about +Z from 0 at 0 s to 90 degrees at 2 s,
    // with EXT_mesh_gpu_instancing copies at x = 0 and x = 10 of its own space: at time t
    // copy i is at 2 x_i (cos a, sin a, 0), a = 45 t degrees (the node's matrix times the
    // copy's, in that order).
    const test::ScratchDir dir;
    test::GltfBuilder b;
    const int pos = b.add<float>({0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3");
    const int copies = b.add<float>({0, 0, 0, 10, 0, 0}, test::kFloat, "VEC3");
    const int times = b.add<float>({0, 2}, test::kFloat, "SCALAR");
    const float h = std::sqrt(0.5f);
    const int turn = b.add<float>({0, 0, 0, 1, 0, 0, h, h}, test::kFloat, "VEC4");
    const std::string members =
        "\"extensionsUsed\":[\"EXT_mesh_gpu_instancing\"],"
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":" +
        std::to_string(pos) +
        "}}]}],\"nodes\":[{\"mesh\":0,\"scale\":[2,2,2],\"extensions\":{"
        "\"EXT_mesh_gpu_instancing\":{\"attributes\":{\"TRANSLATION\":" +
        std::to_string(copies) +
        "}}}}],\"scenes\":[{\"nodes\":[0]}],\"animations\":[{\"samplers\":[{\"input\":" +
        std::to_string(times) + ",\"output\":" + std::to_string(turn) +
        "}],\"channels\":[{\"sampler\":0,\"target\":{\"node\":0,\"path\":\"rotation\"}}]}]";
    const Scene s =
        load_at(b.write(dir, "copies.gltf", members, test::BufferStorage::DataUri), 1.0, 0.5);
    ASSERT_EQ(s.instances.size(), 2u);
    const FrameNeighbours& n = *s.frame_neighbours;
    ASSERT_EQ(n.previous.instances.size(), 2u);
    const double deg = 3.14159265358979 / 180;
    for (size_t i = 0; i < 2; ++i) {
        const double r = 20.0 * double(i);
        for (const auto& [m, angle] : {std::pair<Mat4, double>{n.previous.instances[i], 22.5},
                                       {s.instances[i].to_world.matrix(), 45.0},
                                       {n.next.instances[i], 67.5}}) {
            EXPECT_NEAR(m(0, 3), r * std::cos(angle * deg), 1e-4) << i << " at " << angle;
            EXPECT_NEAR(m(1, 3), r * std::sin(angle * deg), 1e-4) << i << " at " << angle;
        }
    }
}

TEST(GltfFrameNeighbours, CostNothingUnlessAskedFor) {
    const test::ScratchDir dir;
    const Scene s = load_at(neighbours_file(dir), 1.0, 0);
    EXPECT_FALSE(s.frame_neighbours);
    // The mesh at rest is shared: no copy is made for frames nobody looks at.
    EXPECT_EQ(s.instances[0].object, 0u);
    EXPECT_THROW(load_at(neighbours_file(dir), 1.0, -1), SceneError);
}

}  // namespace
}  // namespace penumbra
