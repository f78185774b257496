// The loader's transform motion: nodes posed at shutter open, time steps only for what
// moves within the shutter, their number from the keys and the rotation inside it, and
// animated parents, cameras and GPU instances carried along.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "io/gltf/gltf_loader.h"
#include "support/gltf_builder.h"
#include "support/paths.h"

namespace penumbra {
namespace {

constexpr double kPiD = 3.14159265358979323846;

void expect_near(Vec3 a, Vec3 b, float eps, const std::string& what) {
    EXPECT_NEAR(a.x, b.x, eps) << what;
    EXPECT_NEAR(a.y, b.y, eps) << what;
    EXPECT_NEAR(a.z, b.z, eps) << what;
}

Scene load_at(const std::string& path, double open, double close) {
    GltfLoadOptions o;
    o.shutter_open = open;
    o.shutter_close = close;
    return load_gltf(path, o);
}

std::string box_animated() { return test::shared_path("scenes/khronos/BoxAnimated.gltf"); }

// BoxAnimated: instance 0 is node 3 (static), instance 1 is node 2 (rotating, below the
// translating node 0).
const Instance& by_node(const Scene& s, int node) {
    for (const Instance& i : s.instances)
        if (i.node == node) return i;
    throw std::runtime_error("no instance of node " + std::to_string(node));
}

TEST(GltfNodeMotion, StillAtTimeZeroHasNoMotion) {
    const Scene s = load_gltf(box_animated());
    EXPECT_EQ(s.shutter_open, 0);
    EXPECT_EQ(s.shutter_close, 0);
    ASSERT_EQ(s.instances.size(), 2u);
    for (const Instance& i : s.instances) EXPECT_TRUE(i.motion.empty());
    expect_near(by_node(s, 2).to_world.point({0, 0, 1}), {0, 0, 1}, 1e-6f, "rest pose");
}

TEST(GltfNodeMotion, StillAtATimeIsPosedThen) {
    // t = 1.875: node 0 at y = 2.52, node 2 rotated 90 degrees about X.
    const Scene s = load_at(box_animated(), 1.875, 1.875);
    const Instance& i = by_node(s, 2);
    EXPECT_TRUE(i.motion.empty());
    expect_near(i.to_world.point({0, 0, 1}), {0, 2.52f - 1, 0}, 1e-5f, "posed at 1.875 s");
    EXPECT_TRUE(by_node(s, 3).motion.empty());
}

TEST(GltfNodeMotion, TranslationInsideOneKeyIntervalGetsTwoSteps) {
    // [0.5, 0.75] lies inside node 0's first LINEAR interval [0, 1.25] (0 -> 2.52 in y);
    // node 2's rotation keys start at 1.25, so only the parent's translation moves it.
    const Scene s = load_at(box_animated(), 0.5, 0.75);
    const Instance& i = by_node(s, 2);
    ASSERT_EQ(i.motion.size(), 2u);
    expect_near(i.motion[0].point({0, 0, 0}), {0, 2.52f * 0.4f, 0}, 1e-5f, "open");
    expect_near(i.motion[1].point({0, 0, 0}), {0, 2.52f * 0.6f, 0}, 1e-5f, "close");
    EXPECT_EQ(i.to_world.matrix().m, i.motion[0].matrix().m);
    EXPECT_TRUE(by_node(s, 3).motion.empty());
}

TEST(GltfNodeMotion, RotationGetsAStepPerTenDegrees) {
    // [1.25, 2.5]: node 2 turns 180 degrees about X (one LINEAR interval), so
    // 18 intervals, 19 steps; step k is the slerp at s = k / 18, a rotation by 180 s deg.
    const Scene s = load_at(box_animated(), 1.25, 2.5);
    const Instance& i = by_node(s, 2);
    ASSERT_EQ(i.motion.size(), 19u);
    for (size_t k = 0; k < i.motion.size(); ++k) {
        const double angle = kPiD * double(k) / 18;
        expect_near(i.motion[k].point({0, 0, 1}),
                    {0, float(2.52 - std::sin(angle)), float(std::cos(angle))}, 2e-5f,
                    "step " + std::to_string(k));
    }
}

TEST(GltfNodeMotion, ShutterOutsideTheKeysIsStill) {
    // After the last key (3.71 s) every channel is clamped: nothing moves.
    const Scene s = load_at(box_animated(), 5, 6);
    for (const Instance& i : s.instances) EXPECT_TRUE(i.motion.empty());
    expect_near(by_node(s, 2).to_world.point({0, 0, 1}), {0, 0, -1}, 1e-5f, "final pose");
}

TEST(GltfNodeMotion, FileWithoutAnimationsLoadsAsAStillWhateverTheShutter) {
    const std::string path = test::shared_path("scenes/khronos/Box.gltf");
    const Scene still = load_gltf(path);
    const Scene blurred = load_at(path, 0, 10);
    ASSERT_EQ(still.instances.size(), blurred.instances.size());
    for (size_t k = 0; k < still.instances.size(); ++k) {
        EXPECT_TRUE(blurred.instances[k].motion.empty());
        EXPECT_EQ(still.instances[k].to_world.matrix().m, blurred.instances[k].to_world.matrix().m);
    }
}

TEST(GltfNodeMotion, ShutterClosingBeforeItOpensIsAnError) {
    try {
        load_at(box_animated(), 2, 1);
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("open no later than it closes"), std::string::npos)
            << e.what();
    }
}

// Node 0: camera; node 1: a triangle with GPU instances; node 2: static triangle. Nodes
// 0 and 1 translate along X with keys at `times` (x = key index), interpolated `interp`.
std::string moving_file(const test::ScratchDir& dir, const std::vector<float>& times,
                        const char* interp) {
    test::GltfBuilder b;
    const int pos = b.add<float>({0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3",
                                 "\"min\":[0,0,0],\"max\":[1,1,0]");
    const int inst = b.add<float>({0, 0, 0, 0, 5, 0}, test::kFloat, "VEC3");
    const int in = b.add<float>(times, test::kFloat, "SCALAR");
    std::vector<float> out;
    const bool cubic = std::string(interp) == "CUBICSPLINE";
    for (size_t k = 0; k < times.size(); ++k) {
        if (cubic) out.insert(out.end(), {1, 0, 0});
        out.insert(out.end(), {float(k), 0, 0});
        if (cubic) out.insert(out.end(), {1, 0, 0});
    }
    const int o = b.add<float>(out, test::kFloat, "VEC3");
    const std::string members =
        "\"extensionsUsed\":[\"EXT_mesh_gpu_instancing\"],"
        "\"cameras\":[{\"type\":\"perspective\",\"perspective\":{\"yfov\":0.8,\"znear\":0.1}}],"
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(pos) +
        "}}]}],\"nodes\":[{\"camera\":0,\"translation\":[0,0,5]},{\"mesh\":0,\"extensions\":{"
        "\"EXT_mesh_gpu_instancing\":{\"attributes\":{\"TRANSLATION\":" + std::to_string(inst) +
        "}}}},{\"mesh\":0}],\"scenes\":[{\"nodes\":[0,1,2]}],"
        "\"animations\":[{\"samplers\":[{\"input\":" + std::to_string(in) + ",\"output\":" +
        std::to_string(o) + ",\"interpolation\":\"" + interp + "\"}],\"channels\":["
        "{\"sampler\":0,\"target\":{\"node\":0,\"path\":\"translation\"}},"
        "{\"sampler\":0,\"target\":{\"node\":1,\"path\":\"translation\"}}]}]";
    return b.write(dir, "moving.gltf", members, test::BufferStorage::DataUri);
}

TEST(GltfNodeMotion, CameraAndGpuInstancesMoveWithTheirNode) {
    const test::ScratchDir dir;
    const Scene s = load_at(moving_file(dir, {0, 1}, "LINEAR"), 0.25, 0.75);
    ASSERT_EQ(s.cameras.size(), 1u);
    ASSERT_EQ(s.cameras[0].motion.size(), 2u);
    // The camera node's translation channel replaces its rest translation (0, 0, 5).
    expect_near(s.cameras[0].motion[0].point({0, 0, 0}), {0.25f, 0, 0}, 1e-6f, "camera open");
    expect_near(s.cameras[0].motion[1].point({0, 0, 0}), {0.75f, 0, 0}, 1e-6f, "camera close");
    ASSERT_EQ(s.instances.size(), 3u);
    for (int k = 0; k < 2; ++k) {
        const Instance& i = s.instances[size_t(k)];
        EXPECT_EQ(i.node, 1);
        ASSERT_EQ(i.motion.size(), 2u);
        expect_near(i.motion[1].point({0, 0, 0}), {0.75f, 5.0f * float(k), 0}, 1e-6f,
                    "instance " + std::to_string(k));
    }
    EXPECT_TRUE(s.instances[2].motion.empty());
}

TEST(GltfNodeMotion, StepsFollowTheKeysInsideTheShutter) {
    const test::ScratchDir dir;
    // Ten LINEAR intervals of 0.1 s over the shutter: one step each, 11 steps.
    std::vector<float> times;
    for (int k = 0; k <= 10; ++k) times.push_back(0.1f * float(k));
    Scene s = load_at(moving_file(dir, times, "LINEAR"), 0, 1);
    ASSERT_EQ(s.instances[0].motion.size(), 11u);
    for (int k = 0; k <= 10; ++k)
        EXPECT_NEAR(s.instances[0].motion[size_t(k)].point({0, 0, 0}).x, float(k), 1e-4f) << k;
    // Half the shutter covers five intervals: 6 steps.
    s = load_at(moving_file(dir, times, "LINEAR"), 0, 0.5);
    EXPECT_EQ(s.instances[0].motion.size(), 6u);
    // CUBICSPLINE bends inside an interval: four steps per interval, capped at 65.
    s = load_at(moving_file(dir, {0, 1, 2}, "CUBICSPLINE"), 0, 2);
    EXPECT_EQ(s.instances[0].motion.size(), 9u);
    s = load_at(moving_file(dir, times, "CUBICSPLINE"), 0, 1);
    EXPECT_EQ(s.instances[0].motion.size(), 41u);
    std::vector<float> dense;
    for (int k = 0; k <= 100; ++k) dense.push_back(0.01f * float(k));
    s = load_at(moving_file(dir, dense, "LINEAR"), 0, 1);
    EXPECT_EQ(s.instances[0].motion.size(), 65u);
}

}  // namespace
}  // namespace penumbra

namespace penumbra {
namespace {

// scenes/motion-blur.gltf over [0.5, 1] s (scenes/README.md): the bar turns 90 degrees
// (10 steps), the cube slides inside one key interval (2 steps), the camera eases
// (CUBICSPLINE: 4 steps per 2 s interval, 1 inside half a second), the sphere deforms.
TEST(GltfNodeMotion, MotionBlurSceneStepsAsDocumented) {
    const Scene s = load_at(test::source_path("scenes/motion-blur.gltf"), 0.5, 1);
    EXPECT_TRUE(by_node(s, 1).motion.empty()) << "floor";
    EXPECT_EQ(by_node(s, 2).motion.size(), 2u) << "cube";
    EXPECT_EQ(by_node(s, 3).motion.size(), 10u) << "bar";
    ASSERT_EQ(s.cameras.size(), 1u);
    EXPECT_EQ(s.cameras[0].motion.size(), 2u);
    const Object& sphere = s.objects[by_node(s, 4).object];
    EXPECT_EQ(s.meshes[sphere.meshes[0]].motion_positions.size(), 2u);
    expect_near(by_node(s, 2).motion[1].point({0, 0, 0}), {0, 0.5f, 0.8f}, 1e-5f, "cube");
}

}  // namespace
}  // namespace penumbra
