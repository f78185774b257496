// Skin weights are normalised per vertex over all JOINTS_n/WEIGHTS_n sets, as three.js and
// Blender do: a CesiumMan-like mesh whose weights sum to 0.9 poses as with sum 1, a zero
// or non-finite sum falls back to JOINTS_0's first joint, and one warning per file counts
// the vertices whose sum was off by more than float rounding.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/error.h"
#include "io/gltf/gltf_loader.h"
#include "io/gltf/animation/gltf_skin_weights.h"
#include "support/gltf_builder.h"

namespace penumbra {
namespace {

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

// A skinned triangle drawn by two nodes (0 and 3; node 0's translation is ignored).
// Joint 0 is node 1, static; joint 1 is node 2, child of node 1, animated from z = 2 (its
// bind pose) to z = 4 over [0, 1] s. JOINTS_0 is `joints0`, WEIGHTS_0 `weights0`;
// `weights1` non-empty adds JOINTS_1 = joint 1 everywhere with WEIGHTS_1 = `weights1`.
std::string skinned(const test::ScratchDir& dir, const std::vector<uint8_t>& joints0,
                    const std::vector<float>& weights0, const std::vector<float>& weights1 = {}) {
    test::GltfBuilder b;
    const int pos = b.add<float>({0, 0, 0, 1, 0, 0, 0, 1, 0}, test::kFloat, "VEC3");
    const int j0 = b.add<uint8_t>(joints0, test::kUByte, "VEC4");
    const int w0 = b.add<float>(weights0, test::kFloat, "VEC4");
    std::string second;
    if (!weights1.empty()) {
        const int j1 = b.add<uint8_t>({1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, test::kUByte, "VEC4");
        const int w1 = b.add<float>(weights1, test::kFloat, "VEC4");
        second = ",\"JOINTS_1\":" + std::to_string(j1) + ",\"WEIGHTS_1\":" + std::to_string(w1);
    }
    // Column-major inverse bind matrices: identity, and a translation by (0, 0, -2).
    const int ibm = b.add<float>({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1,  //
                                  1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -2, 1},
                                 test::kFloat, "MAT4");
    const int in = b.add<float>({0, 1}, test::kFloat, "SCALAR");
    const int out = b.add<float>({0, 0, 2, 0, 0, 4}, test::kFloat, "VEC3");
    return b.write(
        dir, "skinned.gltf",
        "\"meshes\":[{\"name\":\"body\",\"primitives\":[{\"attributes\":{\"POSITION\":" +
            std::to_string(pos) + ",\"JOINTS_0\":" + std::to_string(j0) + ",\"WEIGHTS_0\":" +
            std::to_string(w0) + second + "}}]}],\"skins\":[{\"joints\":[1,2],"
            "\"inverseBindMatrices\":" + std::to_string(ibm) +
            "}],\"nodes\":[{\"mesh\":0,\"skin\":0,\"translation\":[100,0,0]},{\"children\":[2]},"
            "{\"translation\":[0,0,2]},{\"mesh\":0,\"skin\":0}],\"scenes\":[{\"nodes\":[0,1,3]}],"
            "\"animations\":[{\"samplers\":[{\"input\":" + std::to_string(in) + ",\"output\":" +
            std::to_string(out) +
            "}],\"channels\":[{\"sampler\":0,\"target\":{\"node\":2,\"path\":\"translation\"}}]}]",
        test::BufferStorage::DataUri);
}

const std::vector<uint8_t> kJoints = {0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0};

// The posed vertices of instance i at 0.5 s (joint 1 one unit above its bind pose), and
// the log of loading them.
std::vector<Vec3> posed(const std::string& path, size_t i, std::string* log = nullptr) {
    GltfLoadOptions o;
    o.shutter_open = o.shutter_close = 0.5;
    testing::internal::CaptureStderr();
    const Scene s = load_gltf(path, o);
    const std::string text = testing::internal::GetCapturedStderr();
    if (log) *log = text;
    const Object& obj = s.objects[s.instances.at(i).object];
    return s.meshes[obj.meshes.at(0)].positions;
}

// One float rounding of a product or quotient near 1 (2^-24 relative, twice).
constexpr float kRounding = 2.0f * 6e-8f * 4.0f;

TEST(GltfSkinWeights, WeightsSummingToPointNinePoseAsWithOne) {
    const test::ScratchDir dir;
    const std::string one = skinned(dir, kJoints, {1, 0, 0, 0, 1, 0, 0, 0, 0.5f, 0.5f, 0, 0});
    const std::vector<Vec3> expected = posed(one, 0);
    ASSERT_EQ(expected.size(), 3u);
    EXPECT_EQ(expected[1], Vec3(1, 0, 1));  // the unscaled weights' pose
    EXPECT_EQ(expected[2], Vec3(0, 1, 0.5f));

    const test::ScratchDir dir2;
    const std::string path =
        skinned(dir2, kJoints, {0.9f, 0, 0, 0, 0.9f, 0, 0, 0, 0.45f, 0.45f, 0, 0});
    std::string log;
    for (size_t node = 0; node < 2; ++node) {
        const std::vector<Vec3> p = posed(path, node, &log);
        for (size_t v = 0; v < 3; ++v)
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(p[v][c], expected[v][c], kRounding) << "vertex " << v;
    }
    // Unnormalised, vertex 1 would sit at 0.9 (1, 0, 1).
    EXPECT_EQ(count(log, "warning: "), 1u) << log;
    EXPECT_EQ(count(log, path + ": skins: the skin weights of 3 vertices do not sum to 1, in 1 "
                                "mesh(es) (meshes[0] 'body'); first: meshes[0].primitives[0] "
                                "vertex 0 sums to 0.900000; each vertex's weights are scaled "
                                "to sum to 1, as three.js and Blender do\n"),
              1u)
        << log;

    GltfLoadOptions strict;
    strict.strict = true;
    try {
        load_gltf(path, strict);
        FAIL() << "no error under --strict";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(path + ": skins: the skin weights of 3 vertices", 0),
                  0u)
            << e.what();
    }
}

// Vertex 0: all zero; vertex 1: NaN. Both take JOINTS_0's first joint (joint 1 here) with
// weight 1, three.js's fallback for a zero sum, and load without an error.
TEST(GltfSkinWeights, ZeroOrNonFiniteSumFollowsTheFirstJoint) {
    const test::ScratchDir dir;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const std::string path = skinned(dir, {1, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0},
                                     {0, 0, 0, 0, 0, nan, 0, 0, 0.5f, 0.5f, 0, 0});
    std::string log;
    const std::vector<Vec3> p = posed(path, 0, &log);
    EXPECT_EQ(p[0], Vec3(0, 0, 1));
    EXPECT_EQ(p[1], Vec3(1, 0, 1));
    EXPECT_EQ(p[2], Vec3(0, 1, 0.5f));
    EXPECT_NE(log.find("the skin weights of 2 vertices do not sum to 1"), std::string::npos)
        << log;
}

// WEIGHTS_0 0.3 on joint 0 and WEIGHTS_1 0.3 on joint 1: half each after normalising over
// both sets.
TEST(GltfSkinWeights, NormalisedOverEverySet) {
    const test::ScratchDir dir;
    const std::string path = skinned(dir, kJoints, {1, 0, 0, 0, 1, 0, 0, 0, 0.3f, 0, 0, 0},
                                     {0, 0, 0, 0, 0, 0, 0, 0, 0.3f, 0, 0, 0});
    const std::vector<Vec3> p = posed(path, 0);
    EXPECT_NEAR(p[2].z, 0.5f, kRounding);
    EXPECT_EQ(p[1], Vec3(1, 0, 1));
}

// The count's allowance is glTF-Validator's: 2e-7 per nonzero weight, the float32 rounding
// of a sum of weights that an exporter normalised. One ulp of 1 above (1.19e-7) is inside
// it for one weight, two ulps (2.38e-7) are not; normalized unsigned bytes 128 + 127 (read
// as floats, each rounded) sum to 1 within it; 0.9995 is a deviation like any other.
TEST(GltfSkinWeights, CountsDeviationsBeyondFloatRounding) {
    const float ulp = std::nextafter(1.0f, 2.0f) - 1.0f;
    SkinWeights w;
    w.influences = 1;
    w.weights = {1 + ulp, 0, 0, 0,  1 + 2 * ulp, 0, 0, 0,  128 / 255.0f, 127 / 255.0f, 0, 0,
                 0.9995f, 0, 0, 0,  0.25f, 0.25f, 0.25f, 0.25f};
    normalize_skin_weights(w, 5);
    EXPECT_EQ(w.renormalized, 2u);
    EXPECT_EQ(w.example, 1u);
    EXPECT_NEAR(w.example_sum, 1 + 2 * double(ulp), 1e-12);
    for (size_t v = 0; v < 5; ++v) {
        double sum = 0;
        for (int c = 0; c < 4; ++c) sum += w.weights[4 * v + size_t(c)];
        EXPECT_NEAR(sum, 1.0, 2 * double(ulp)) << "vertex " << v;
    }
}

}  // namespace
}  // namespace penumbra
