// `render --aov vector` end to end against the analytic motion of a unit box seen by a
// pinhole camera looking down -Z from 5 units away (yfov 2 atan(0.5), 64 x 64 pixels, a box
// filter): every point of the box's front face (z = 0.5) lies at depth 4.5, so a motion
// parallel to the image plane moves each of them by the same number of pixels,
// 32 * d / (4.5 * 0.5) for a world distance d. The layer follows Cycles' Vector pass:
// X, Y = previous - current, Z, W = current - next, in pixels with +Y up the image. The
// farm's bands merge to the vectors of one machine.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "support/cli_process.h"
#include "support/exr_pixels.h"
#include "support/gltf_builder.h"

namespace penumbra {
namespace {

constexpr int kSize = 64;
constexpr double kFps = 24;
constexpr double kFaceDepth = 4.5;  // camera at z = 5, the box's front face at z = 0.5
constexpr double kTanHalfFov = 0.5;

// Pixels a world distance d parallel to the image plane at the front face's depth spans.
double pixels(double d) { return 0.5 * kSize * d / (kFaceDepth * kTanHalfFov); }

// The box (node 0, centred on the origin) and the camera (node 1, at (0, 0, 5)), each
// translated LINEARly by `box_velocity` / `camera_velocity` units a second, and the box
// turned about +Z (towards the camera) by `spin` radians a second (keys at 0 and 2 s); no
// animation at all when all are 0.
std::string box_scene(const test::ScratchDir& dir, const std::vector<float>& box_velocity,
                      const std::vector<float>& camera_velocity, float spin = 0) {
    test::GltfBuilder b;
    std::vector<float> p;
    for (int i = 0; i < 8; ++i)
        for (int axis = 0; axis < 3; ++axis) p.push_back((i >> axis & 1) ? 0.5f : -0.5f);
    const int pos = b.add<float>(p, test::kFloat, "VEC3");
    const int idx = b.add<uint16_t>({0, 1, 3, 0, 3, 2, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                                     2, 3, 7, 2, 7, 6, 0, 2, 6, 0, 6, 4, 1, 3, 7, 1, 7, 5},
                                    test::kUShort, "SCALAR");
    const std::vector<float> camera_from = {0, 0, 5};
    std::string nodes = "\"nodes\":[{\"mesh\":0},{\"camera\":0,\"translation\":[0,0,5]}]";
    std::string animations;
    std::vector<std::string> samplers, channels;
    auto animate = [&](int node, const std::vector<float>& from, const std::vector<float>& v) {
        if (v[0] == 0 && v[1] == 0 && v[2] == 0) return;
        const int times = b.add<float>({0, 2}, test::kFloat, "SCALAR");
        const int values = b.add<float>(
            {from[0], from[1], from[2], from[0] + 2 * v[0], from[1] + 2 * v[1], from[2] + 2 * v[2]},
            test::kFloat, "VEC3");
        samplers.push_back("{\"input\":" + std::to_string(times) + ",\"output\":" +
                           std::to_string(values) + ",\"interpolation\":\"LINEAR\"}");
        channels.push_back("{\"sampler\":" + std::to_string(samplers.size() - 1) +
                           ",\"target\":{\"node\":" + std::to_string(node) +
                           ",\"path\":\"translation\"}}");
    };
    animate(0, {0, 0, 0}, box_velocity);
    animate(1, camera_from, camera_velocity);
    if (spin != 0) {
        // LINEAR rotation is a slerp: the angle grows evenly, from 0 to 2 spin (< pi).
        const int times = b.add<float>({0, 2}, test::kFloat, "SCALAR");
        const int values =
            b.add<float>({0, 0, 0, 1, 0, 0, std::sin(spin), std::cos(spin)}, test::kFloat, "VEC4");
        samplers.push_back("{\"input\":" + std::to_string(times) + ",\"output\":" +
                           std::to_string(values) + ",\"interpolation\":\"LINEAR\"}");
        channels.push_back("{\"sampler\":" + std::to_string(samplers.size() - 1) +
                           ",\"target\":{\"node\":0,\"path\":\"rotation\"}}");
    }
    auto join = [](const std::vector<std::string>& v) {
        std::string s;
        for (const std::string& x : v) s += (s.empty() ? "" : ",") + x;
        return s;
    };
    if (!samplers.empty())
        animations = ",\"animations\":[{\"samplers\":[" + join(samplers) + "],\"channels\":[" +
                     join(channels) + "]}]";
    const std::string members =
        "\"materials\":[{\"doubleSided\":true}],"
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":" +
        std::to_string(pos) + "},\"indices\":" + std::to_string(idx) +
        ",\"material\":0}]}],"
        "\"cameras\":[{\"type\":\"perspective\",\"perspective\":{\"yfov\":" +
        std::to_string(2 * std::atan(kTanHalfFov)) + ",\"aspectRatio\":1,\"znear\":0.1}}]," +
        nodes + ",\"scenes\":[{\"nodes\":[0,1]}]" + animations;
    return b.write(dir, "box.gltf", members, test::BufferStorage::DataUri);
}

// Renders `scene` at `time` with the vector layer; its pixels.
test::Pixels render_vectors(const test::ScratchDir& dir, const std::string& scene,
                            const std::string& time) {
    const std::string exr = dir.file("v.exr");
    const test::CliResult r = test::run_penumbra({"render",
                                                  scene,
                                                  "-o",
                                                  exr,
                                                  "--width",
                                                  std::to_string(kSize),
                                                  "--height",
                                                  std::to_string(kSize),
                                                  "--spp",
                                                  "4",
                                                  "--filter",
                                                  "box",
                                                  "--time",
                                                  time,
                                                  "--fps",
                                                  "24",
                                                  "--aov",
                                                  "vector,depth,position",
                                                  "--env-color",
                                                  "1",
                                                  "1",
                                                  "1",
                                                  "--no-preview",
                                                  "-q"});
    EXPECT_EQ(r.status, 0) << r.output;
    return test::read_pixels(exr);
}

float at(const test::Pixels& p, const std::string& name, int x, int y) {
    const auto it = std::find(p.channels.begin(), p.channels.end(), name);
    if (it == p.channels.end()) {
        ADD_FAILURE() << "no channel " << name;
        return -100;
    }
    const size_t c = size_t(it - p.channels.begin());
    return p.data[(size_t(y) * p.width + x) * p.channels.size() + c];
}

// Raster coordinates are at most 64 pixels, where a float's spacing is 7.6e-6 px: each
// vector is a difference of two projections of interpolated, transformed points, exact to
// a few of those spacings (the largest error seen is 4.7e-6 px); this allows 13. A wrong
// frame, sign or axis is off by about a pixel.
constexpr float kTolerance = 1e-4f;

// Every pixel of rows [y0, y1] and columns [x0, x1], all on the front face (its samples
// too, with the box filter) holds `expected` (X, Y, Z, W).
void expect_vectors(const test::Pixels& p, int x0, int x1, int y0, int y1,
                    const std::vector<double>& expected) {
    const char* names[4] = {"Vector.X", "Vector.Y", "Vector.Z", "Vector.W"};
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x)
            for (int c = 0; c < 4; ++c)
                EXPECT_NEAR(at(p, names[c], x, y), expected[size_t(c)], kTolerance)
                    << names[c] << " at " << x << "," << y;
}

TEST(MotionVectorCli, AMovingBoxMovesByItsProjectedSpeed) {
    const test::ScratchDir dir;
    // 2.4 units a second to the right: 0.1 a frame at 24 fps. At 0.5 s the box's centre is
    // at x = 1.2, its front face over raster x 32 + 14.2 * [0.7, 1.7] = [41.96, 56.18] and
    // y 32 -/+ 7.1; its left side shows left of that.
    const test::Pixels p = render_vectors(dir, box_scene(dir, {2.4f, 0, 0}, {0, 0, 0}), "0.5");
    ASSERT_TRUE(p.error.empty()) << p.error;
    const double v = pixels(2.4 / kFps);
    // The previous frame is to the left and the next to the right: both differences -v.
    expect_vectors(p, 43, 55, 26, 37, {-v, 0, -v, 0});
    // These pixels see the front face (the distance grows off the axis: at most 4.9 here).
    EXPECT_GT(at(p, "Depth.Z", 43, 26), kFaceDepth);
    EXPECT_LT(at(p, "Depth.Z", 55, 37), 5.0);
    // Background: no surface, no vector.
    EXPECT_EQ(at(p, "Depth.Z", 0, 0), 1e10f) << "pixel 0,0 sees the background";
    for (const char* c : {"Vector.X", "Vector.Y", "Vector.Z", "Vector.W"})
        EXPECT_EQ(at(p, c, 0, 0), 0.0f) << c << " at 0,0";
}

TEST(MotionVectorCli, AMovingCameraMovesAStillBoxTheOtherWay) {
    const test::ScratchDir dir;
    // The camera rises 1.2 units a second; the box at the origin then sinks in the image:
    // it stood higher (+Y, up the image) a frame before and stands lower a frame after.
    const test::Pixels p = render_vectors(dir, box_scene(dir, {0, 0, 0}, {0, 1.2f, 0}), "0.25");
    ASSERT_TRUE(p.error.empty()) << p.error;
    const double v = pixels(1.2 / kFps);
    // At 0.25 s the camera is at y = 0.3: the face spans raster y (image rows, down)
    // 32 + 14.2 * [-0.2, 0.8] = [29.2, 43.4] and columns 32 -/+ 7.1.
    expect_vectors(p, 26, 37, 31, 42, {0, v, 0, v});
}

TEST(MotionVectorCli, ATurningBoxMovesEachPointAlongItsCircle) {
    const test::ScratchDir dir;
    // 0.6 radians a second about the view axis, counter-clockwise as the camera sees it:
    // the front face stays at depth 4.5, and a point p of it (world x, y) was at R(-a) p a
    // frame before and will be at R(a) p a frame after (a = 0.6 / 24). Both maps are
    // linear, so a pixel's mean vector is that of its samples' mean point, its Position.
    const float spin = 0.6f;
    const test::Pixels p = render_vectors(dir, box_scene(dir, {0, 0, 0}, {0, 0, 0}, spin), "0.5");
    ASSERT_TRUE(p.error.empty()) << p.error;
    const double a = spin / kFps, k = pixels(1);
    int checked = 0;
    // The face, turned 0.3 rad, still covers the disc of radius 0.5 (7.1 px) around its
    // centre: the pixels whose corners lie in it, centres within 6.1 px.
    for (int y = 26; y < 38; ++y)
        for (int x = 26; x < 38; ++x) {
            const double cx = x + 0.5 - 32, cy = y + 0.5 - 32;
            if (std::hypot(cx, cy) > 0.5 * k - 1) continue;
            const double px = at(p, "Position.X", x, y), py = at(p, "Position.Y", x, y);
            // Raster is Cycles': +Y up the image, as world +Y.
            const double prev_x = std::cos(a) * px + std::sin(a) * py,
                         prev_y = -std::sin(a) * px + std::cos(a) * py;
            const double next_x = std::cos(a) * px - std::sin(a) * py,
                         next_y = std::sin(a) * px + std::cos(a) * py;
            expect_vectors(
                p, x, x, y, y,
                {k * (prev_x - px), k * (prev_y - py), k * (px - next_x), k * (py - next_y)});
            ++checked;
        }
    EXPECT_GT(checked, 80);
}

TEST(MotionVectorCli, AStillSceneHasNoMotionAnywhere) {
    const test::ScratchDir dir;
    const test::Pixels p = render_vectors(dir, box_scene(dir, {0, 0, 0}, {0, 0, 0}), "0");
    ASSERT_TRUE(p.error.empty()) << p.error;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            for (const char* c : {"Vector.X", "Vector.Y", "Vector.Z", "Vector.W"})
                ASSERT_EQ(at(p, c, x, y), 0.0f) << c << " at " << x << "," << y;
    // The still box is in view: its vectors are 0 because it stands still, not because
    // nothing was hit (the depth is the distance to the front face's centre, 4.5).
    EXPECT_NEAR(at(p, "Depth.Z", 32, 32), kFaceDepth, 0.01);
}

TEST(MotionVectorCli, FarmBandsMergeToTheVectorsOfOneMachine) {
    const test::ScratchDir dir;
    const std::string scene = box_scene(dir, {2.4f, 0, 0}, {0, 0, 0}, 0.6f);
    auto job = [&](const std::string& name, const std::string& out_dir) {
        return dir.write(name, R"({"defaults": {"width": 32, "height": 32, "spp": 2, "time": 0.5,
  "fps": 24, "aov": "vector", "out_dir": ")" +
                                   dir.file(out_dir) + R"("},
  "jobs": [{"scene": ")" + scene + R"(", "bands": 3, "name": "box.exr"}]})");
    };
    const test::CliResult ref =
        test::run_penumbra({"render", "--job", job("ref.json", "ref"), "-q"});
    ASSERT_EQ(ref.status, 0) << ref.output;
    const std::string farm = job("farm.json", "farm");
    for (int i = 0; i < 3; ++i) {
        const test::CliResult t =
            test::run_penumbra({"farm", "task", farm, "--index", std::to_string(i)});
        EXPECT_EQ(t.status, 0) << i << ": " << t.output;
    }
    const test::CliResult m = test::run_penumbra({"farm", "merge", farm});
    ASSERT_EQ(m.status, 0) << m.output;
    EXPECT_TRUE(test::same_pixels(dir.file("ref/box.exr"), dir.file("farm/box.exr")));
    const test::Pixels p = test::read_pixels(dir.file("farm/box.exr"));
    ASSERT_TRUE(p.error.empty()) << p.error;
    EXPECT_LT(at(p, "Vector.X", 24, 16), -0.1f) << "the box moves right";
}

}  // namespace
}  // namespace penumbra
