// Animation sampling against values worked out by hand from the keyframes, following
// glTF 2.0 Appendix C: BoxAnimated (Khronos) for LINEAR translation and slerp, and small
// synthetic files for STEP, CUBICSPLINE (tangents scaled by the key interval), the
// shortest-path slerp and morph weights.
#include "io/gltf/animation/gltf_animation.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "support/gltf_builder.h"
#include "support/paths.h"

namespace penumbra {
namespace {

constexpr double kPiD = 3.14159265358979323846;

void expect_near(const std::vector<double>& got, const std::vector<double>& want, double tol,
                 const std::string& what) {
    ASSERT_EQ(got.size(), want.size()) << what;
    for (size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(got[i], want[i], tol) << what << " [" << i << "]";
}

// BoxAnimated.gltf: node 0 translates along +Y through keys at 0, 1.25, 2.5 and
// 3.70833 s with values 0, 2.52, 2.52, 0; node 2 rotates from (0,0,0,-1) at 1.25 s to
// (1,0,0,4.49e-11) at 2.5 s, both LINEAR.
TEST(GltfAnimation, BoxAnimatedTranslationIsPiecewiseLinear) {
    const GltfAnimations a = load_gltf_animations(test::shared_path("scenes/khronos/BoxAnimated.gltf"));
    const NodeChannels* n0 = a.node(0);
    ASSERT_TRUE(n0 && n0->translation);
    EXPECT_FALSE(n0->rotation || n0->scale || n0->weights);
    const AnimationCurve& c = *n0->translation;
    EXPECT_EQ(c.interpolation, Interpolation::Linear);
    const double t3 = double(3.708329916000366f);
    expect_near(c.sample(-1.0), {0, 0, 0}, 1e-12, "before the first key");
    expect_near(c.sample(0.625), {0, 0.5 * 2.52, 0}, 1e-6, "halfway to key 1");
    expect_near(c.sample(2.0), {0, 2.52, 0}, 1e-6, "between equal keys");
    // (3 - 2.5) / (3.70833 - 2.5) of the way down from 2.52 to 0.
    expect_near(c.sample(3.0), {0, 2.52 * (1 - 0.5 / (t3 - 2.5)), 0}, 1e-6, "last interval");
    expect_near(c.sample(10.0), {0, 0, 0}, 1e-12, "after the last key");
    EXPECT_EQ(a.node(1), nullptr);
}

TEST(GltfAnimation, BoxAnimatedRotationIsSlerped) {
    const GltfAnimations a = load_gltf_animations(test::shared_path("scenes/khronos/BoxAnimated.gltf"));
    const NodeChannels* n2 = a.node(2);
    ASSERT_TRUE(n2 && n2->rotation);
    const AnimationCurve& c = *n2->rotation;
    expect_near(c.sample(0.0), {0, 0, 0, -1}, 1e-12, "clamped to key 0");
    // The keys are 90 degrees apart (|q0.q1| = 4.5e-11, a = pi/2) with a negative dot
    // product, so q1 enters negated: q(s) = sin(a(1-s)) q0 - sin(a s) q1.
    const double h = std::sqrt(0.5);
    expect_near(c.sample(1.875), {-h, 0, 0, -h}, 1e-6, "s = 0.5");
    expect_near(c.sample(1.5625), {-std::sin(kPiD / 8), 0, 0, -std::cos(kPiD / 8)}, 1e-6,
                "s = 0.25");
    expect_near(c.sample(3.0), {1, 0, 0, 4.4896593387466766e-11}, 1e-7, "clamped to key 1");
    // The node's pose: rest translation and scale, animated rotation.
    NodePose rest;
    rest.t[0] = 5;
    const NodePose p = a.pose(2, rest, 1.875);
    EXPECT_EQ(p.t[0], 5);
    EXPECT_NEAR(p.r[0], -h, 1e-6);
    EXPECT_NEAR(p.r[3], -h, 1e-6);
}

// Node 0: CUBICSPLINE translation (keys at 1 and 3 s), LINEAR rotation whose second key
// is the negated 90-degree Z rotation, STEP scale. Node 1: mesh with two morph targets
// and LINEAR weights.
std::string synthetic_file(const test::ScratchDir& dir) {
    test::GltfBuilder b;
    const int pos = b.add<float>({0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3",
                                 "\"min\":[0,0,0],\"max\":[1,1,0]");
    const int tgt = b.add<float>({0, 0, 1, 0, 0, 1, 0, 0, 1}, test::kFloat, "VEC3",
                                 "\"min\":[0,0,1],\"max\":[0,0,1]");
    const int t_in = b.add<float>({1, 3}, test::kFloat, "SCALAR");
    // Per key: in-tangent, value, out-tangent.
    const int t_out = b.add<float>({9, 9, 9, 0, 0, 0, 1, 0, 0,  //
                                    0, -2, 0, 4, 2, 0, 7, 7, 7},
                                   test::kFloat, "VEC3");
    const float h = float(std::sqrt(0.5));
    const int r_in = b.add<float>({0, 1}, test::kFloat, "SCALAR");
    const int r_out = b.add<float>({0, 0, 0, 1, 0, 0, -h, -h}, test::kFloat, "VEC4");
    const int s_in = b.add<float>({0, 1, 2}, test::kFloat, "SCALAR");
    const int s_out = b.add<float>({1, 1, 1, 2, 2, 2, 3, 3, 3}, test::kFloat, "VEC3");
    const int w_in = b.add<float>({0, 2}, test::kFloat, "SCALAR");
    const int w_out = b.add<float>({0, 1, 1, 0}, test::kFloat, "SCALAR");
    auto sampler = [](int in, int out, const char* interp) {
        return "{\"input\":" + std::to_string(in) + ",\"output\":" + std::to_string(out) +
               ",\"interpolation\":\"" + interp + "\"}";
    };
    auto channel = [](int s, int node, const char* path) {
        return "{\"sampler\":" + std::to_string(s) + ",\"target\":{\"node\":" +
               std::to_string(node) + ",\"path\":\"" + path + "\"}}";
    };
    const std::string members =
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(pos) +
        "},\"targets\":[{\"POSITION\":" + std::to_string(tgt) + "},{\"POSITION\":" +
        std::to_string(tgt) + "}]}]}],"
        "\"nodes\":[{},{\"mesh\":0}],\"scenes\":[{\"nodes\":[0,1]}],"
        "\"animations\":[{\"samplers\":[" +
        sampler(t_in, t_out, "CUBICSPLINE") + "," + sampler(r_in, r_out, "LINEAR") + "," +
        sampler(s_in, s_out, "STEP") + "," + sampler(w_in, w_out, "LINEAR") +
        "],\"channels\":[" + channel(0, 0, "translation") + "," + channel(1, 0, "rotation") +
        "," + channel(2, 0, "scale") + "," + channel(3, 1, "weights") + "]}]";
    return b.write(dir, "anim.gltf", members, test::BufferStorage::DataUri);
}

TEST(GltfAnimation, CubicSplineUsesTangentsScaledByTheKeyInterval) {
    const test::ScratchDir dir;
    const GltfAnimations a = load_gltf_animations(synthetic_file(dir));
    const AnimationCurve& c = *a.node(0)->translation;
    EXPECT_EQ(c.interpolation, Interpolation::CubicSpline);
    // td = 2; v0 = (0,0,0), b0 = (1,0,0), v1 = (4,2,0), a1 = (0,-2,0).
    // s = 0.5: h00 = h01 = 0.5, h10 = 0.125, h11 = -0.125:
    // x = 2 * 0.125 * 1 + 0.5 * 4 = 2.25; y = 0.5 * 2 + 2 * -0.125 * -2 = 1.5.
    expect_near(c.sample(2.0), {2.25, 1.5, 0}, 1e-6, "s = 0.5");
    // s = 0.25: h10 = 0.140625, h01 = 0.15625, h11 = -0.046875.
    expect_near(c.sample(1.5), {0.90625, 0.5, 0}, 1e-6, "s = 0.25");
    // Outside the keys: the key values, never the tangents.
    expect_near(c.sample(0.0), {0, 0, 0}, 0, "before");
    expect_near(c.sample(4.0), {4, 2, 0}, 0, "after");
}

TEST(GltfAnimation, SlerpTakesTheShortestPath) {
    const test::ScratchDir dir;
    const GltfAnimations a = load_gltf_animations(synthetic_file(dir));
    const AnimationCurve& c = *a.node(0)->rotation;
    // Key 1 is -(90 degrees about Z): the short way is +90 degrees about Z, so at s the
    // rotation is 90 s degrees about Z, (0, 0, sin(45 s deg), cos(45 s deg)).
    for (double s : {0.25, 0.5, 0.75}) {
        const double half = s * kPiD / 4;
        expect_near(c.sample(s), {0, 0, std::sin(half), std::cos(half)}, 1e-6,
                    "s = " + std::to_string(s));
    }
}

TEST(GltfAnimation, StepHoldsEachKeyUntilTheNext) {
    const test::ScratchDir dir;
    const GltfAnimations a = load_gltf_animations(synthetic_file(dir));
    const AnimationCurve& c = *a.node(0)->scale;
    EXPECT_EQ(c.interpolation, Interpolation::Step);
    expect_near(c.sample(-1), {1, 1, 1}, 0, "before");
    expect_near(c.sample(0.999), {1, 1, 1}, 0, "just before key 1");
    expect_near(c.sample(1.0), {2, 2, 2}, 0, "at key 1");
    expect_near(c.sample(1.5), {2, 2, 2}, 0, "between keys 1 and 2");
    expect_near(c.sample(5.0), {3, 3, 3}, 0, "after");
}

TEST(GltfAnimation, MorphWeightsInterpolatePerTarget) {
    const test::ScratchDir dir;
    const GltfAnimations a = load_gltf_animations(synthetic_file(dir));
    const NodeChannels* n1 = a.node(1);
    ASSERT_TRUE(n1 && n1->weights);
    EXPECT_FALSE(n1->animates_transform());
    EXPECT_EQ(n1->weights->width, 2u);
    expect_near(n1->weights->sample(0.5), {0.25, 0.75}, 1e-12, "t = 0.5");
    expect_near(n1->weights->sample(3.0), {1, 0}, 0, "after");
}

TEST(GltfAnimation, FileWithoutAnimationsHasNone) {
    const GltfAnimations a = load_gltf_animations(test::shared_path("scenes/khronos/Box.gltf"));
    EXPECT_TRUE(a.empty());
    EXPECT_EQ(a.node(0), nullptr);
}

}  // namespace
}  // namespace penumbra
