// --frames end to end: every frame of a file renders from one load of it (parsed and its
// images decoded once, posed per frame), and from one accelerator while nothing moves; each
// frame is bitwise the image a render of that frame alone gives, for rigid and skinned
// animation, textures, animated materials, motion blur and still files.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "support/animated_scene.h"
#include "support/cli_process.h"
#include "support/exr_pixels.h"
#include "support/paths.h"

namespace penumbra {
namespace {

using test::run_penumbra;

const std::string kBoxAnimated = test::shared_path("scenes/khronos/BoxAnimated.gltf");  // rigid
const std::string kSkinnedTubes = test::source_path("scenes/skinned-tubes.gltf");
const std::string kFox = test::shared_path("scenes/wild/Fox/Fox.glb");         // skinned, textured
const std::string kCornellBox = test::source_path("scenes/cornell-box.gltf");  // still

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = 0; (at = text.find(what, at)) != std::string::npos; ++at) ++n;
    return n;
}

std::vector<std::string> render_args(const std::string& scene, std::vector<std::string> more) {
    std::vector<std::string> a = {"render", scene, "--width", "24", "--height",    "18",
                                  "--spp",  "2",   "--fps",   "8",  "--no-preview"};
    a.insert(a.end(), more.begin(), more.end());
    return a;
}

std::string frame_name(const std::string& dir, int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "/f_%04d.exr", frame);
    return dir + name;
}

// Frames 1-3 in one batch against each frame rendered by a process of its own. `kept`: how
// many frames take the previous frame's accelerator (those where nothing moved).
// The images go under `folder`.
void expect_frames_match_single_renders(const std::string& folder, const std::string& scene,
                                        const std::vector<std::string>& more, size_t kept) {
    std::vector<std::string> batch = more;
    for (const std::string& a : std::vector<std::string>{
             "--frames", "1-3", "--out-dir", folder + "/batch", "--name", "f_{frame}.exr"})
        batch.push_back(a);
    const auto r = run_penumbra(render_args(scene, batch));
    ASSERT_EQ(r.status, 0) << r.output;
    // One parse and image decode; the later frames only pose the file.
    EXPECT_EQ(count(r.output, "load and build:"), 1u) << r.output;
    EXPECT_EQ(count(r.output, "pose and build:"), 2u) << r.output;
    EXPECT_EQ(count(r.output, "accelerator kept"), kept) << r.output;
    for (int f = 1; f <= 3; ++f) {
        std::vector<std::string> alone = more;
        for (const std::string& a : std::vector<std::string>{
                 "--frame", std::to_string(f), "-o", frame_name(folder + "/alone", f), "-q"})
            alone.push_back(a);
        const auto one = run_penumbra(render_args(scene, alone));
        ASSERT_EQ(one.status, 0) << one.output;
        EXPECT_TRUE(
            test::same_pixels(frame_name(folder + "/batch", f), frame_name(folder + "/alone", f)))
            << scene << " frame " << f;
    }
}

// Moving instances: each frame builds its accelerator.
TEST(FramesCli, RigidAnimationFramesEqualSingleFrameRenders) {
    const test::ScratchDir dir;
    expect_frames_match_single_renders(dir.file("embree"), kBoxAnimated, {}, 0);
}

TEST(FramesCli, MotionBlurredFramesEqualSingleFrameRenders) {
    const test::ScratchDir dir;
    expect_frames_match_single_renders(dir.file("embree"), kBoxAnimated, {"--shutter", "0.5"}, 0);
}

// Deforming meshes, appended to the shared ones at every pose.
TEST(FramesCli, SkinnedFramesEqualSingleFrameRenders) {
    const test::ScratchDir dir;
    expect_frames_match_single_renders(dir.file("embree"), kSkinnedTubes, {"--shutter", "0.5"}, 0);
    expect_frames_match_single_renders(dir.file("bvh"), kSkinnedTubes, {"--accel", "bvh"}, 0);
}

TEST(FramesCli, TexturedSkinnedFramesEqualSingleFrameRenders) {
    const test::ScratchDir dir;
    expect_frames_match_single_renders(dir.file("embree"), kFox, {}, 0);
}

// Materials animated through KHR_animation_pointer are read again at every pose, and
// their meshes with them: nothing is kept.
TEST(FramesCli, AnimatedMaterialFramesEqualSingleFrameRenders) {
    const test::ScratchDir dir;
    expect_frames_match_single_renders(dir.file("embree"), test::animated_scene(dir),
                                       {"--shutter", "0.5"}, 0);
}

// A file without animation: every frame after the first keeps the first one's
// accelerator, with either accelerator.
TEST(FramesCli, StillFramesShareOneAccelerator) {
    const test::ScratchDir dir;
    expect_frames_match_single_renders(dir.file("embree"), kCornellBox, {}, 2);
    expect_frames_match_single_renders(dir.file("bvh"), kCornellBox, {"--accel", "bvh"}, 2);
}

}  // namespace
}  // namespace penumbra
