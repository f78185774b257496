// Out-of-spec but renderable mesh data, one summary warning per kind and file
// (io/gltf/gltf_mesh_checks.cpp): POSITION accessors without min/max or with a min/max the
// data disagree with, index counts that are not whole triangles, primitives without
// triangles. --strict makes each an error. Also: loaded meshes are not duplicated.
#include "io/gltf/gltf_mesh_checks.h"

#include <gtest/gtest.h>

#include <cstring>

#include "core/accel/embree_accel.h"
#include "core/error.h"
#include "core/scene/scene_stats.h"
#include "io/gltf/gltf_loader.h"
#include "support/gltf_builder.h"

namespace penumbra {
namespace {

using test::GltfBuilder;
using test::ScratchDir;

const std::vector<float> kTriangle = {0, 0, 0, 1, 0, 0, 0, 2, 0};

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

std::string warnings_of(const std::string& path, Scene* out = nullptr) {
    testing::internal::CaptureStderr();
    Scene s = load_gltf(path);
    if (out) *out = std::move(s);
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

std::string primitives_scene(const std::vector<std::string>& prims) {
    std::string list;
    for (size_t i = 0; i < prims.size(); ++i) list += (i ? "," : "") + prims[i];
    return "\"meshes\":[{\"primitives\":[" + list +
           "]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],\"scene\":0";
}

std::string position_prim(int accessor) {
    return "{\"attributes\":{\"POSITION\":" + std::to_string(accessor) + "}}";
}

// Three primitives over two POSITION accessors without min/max (one used twice) and one
// with them: one warning counting accessors, not primitives; bounds from the data.
TEST(GltfMeshChecks, MissingPositionBoundsAreOneWarning) {
    const ScratchDir dir;
    GltfBuilder b;
    const int bounded = b.add(kTriangle, test::kFloat, "VEC3");  // the builder adds bounds
    // Two unbounded accessors (add_accessor adds none) into one view of two triangles.
    std::vector<float> data = kTriangle;
    const size_t offset = b.bytes().size();
    b.bytes().resize(offset + 2 * data.size() * sizeof(float));
    std::memcpy(b.bytes().data() + offset, data.data(), data.size() * sizeof(float));
    for (float& v : data) v *= 3;
    std::memcpy(b.bytes().data() + offset + data.size() * sizeof(float), data.data(),
                data.size() * sizeof(float));
    b.add_view(offset, 2 * data.size() * sizeof(float));
    const int view = 1;
    const int a = b.add_accessor(view, 0, test::kFloat, "VEC3", 3);
    const int c = b.add_accessor(view, data.size() * sizeof(float), test::kFloat, "VEC3", 3);
    const std::string path = b.write(dir, "unbounded.gltf",
                                     primitives_scene({position_prim(a), position_prim(bounded),
                                                       position_prim(c), position_prim(a)}),
                                     test::BufferStorage::DataUri);
    Scene s;
    const std::string log = warnings_of(path, &s);
    EXPECT_EQ(count(log, "warning: "), 1u) << log;
    EXPECT_EQ(count(log, path + ": accessors: 2 POSITION accessor(s) have no min/max (glTF "
                                "requires them); bounds computed from the data (accessors[1], "
                                "accessors[2])\n"),
              1u)
        << log;
    ASSERT_EQ(s.meshes.size(), 4u);
    EXPECT_EQ(s.meshes[2].bounds.hi.y, 6.0f);
    EXPECT_EQ(strict_error(path).rfind(path + ": accessors: 2 POSITION accessor(s) have no "
                                              "min/max",
                                       0),
              0u);
}

// min/max printed to 6 digits pass; a max below the data, a min below it by more than
// 1e-4 of the size, and a quantized accessor's raw bounds that do not map onto its data
// do not: one warning for the three, and the data's bounds are used.
TEST(GltfMeshChecks, WrongPositionBoundsAreOneWarning) {
    const ScratchDir dir;
    GltfBuilder b;
    const std::vector<float> third = {0, 0, 0, 1.0f / 3, 0, 0, 0, 2.0f / 3, 0};
    const int rounded =
        b.add(third, test::kFloat, "VEC3", "\"min\":[0,0,0],\"max\":[0.333333,0.666667,0]");
    const int low_max = b.add(kTriangle, test::kFloat, "VEC3", "\"min\":[0,0,0],\"max\":[1,1.5,0]");
    const int loose_min =
        b.add(kTriangle, test::kFloat, "VEC3", "\"min\":[-0.01,0,0],\"max\":[1,2,0]");
    // Normalized unsigned short: raw bounds 0..65535 map to 0..1.
    const std::vector<uint16_t> q = {0, 0, 0, 65535, 0, 0, 0, 65535, 0};
    const int quantized = b.add(q, test::kUShort, "VEC3",
                                "\"normalized\":true,\"min\":[0,0,0],\"max\":[65535,65535,0]");
    const int quantized_wrong =
        b.add(q, test::kUShort, "VEC3", "\"normalized\":true,\"min\":[0,0,0],\"max\":[1,1,0]");
    const std::string path = b.write(
        dir, "wrong.gltf",
        primitives_scene({position_prim(rounded), position_prim(low_max), position_prim(loose_min),
                          position_prim(quantized), position_prim(quantized_wrong)}) +
            ",\"extensionsUsed\":[\"KHR_mesh_quantization\"],"
            "\"extensionsRequired\":[\"KHR_mesh_quantization\"]",
        test::BufferStorage::DataUri);
    Scene s;
    const std::string log = warnings_of(path, &s);
    EXPECT_EQ(count(log, "warning: "), 1u) << log;
    EXPECT_EQ(count(log, path + ": accessors: 3 POSITION accessor(s) have a min/max that "
                                "disagrees with their data; bounds computed from the data "
                                "(accessors[1] min [0, 0, 0] max [1, 1.5, 0], data [0, 0, 0] "
                                "to [1, 2, 0], accessors[2] min [-0.01, 0, 0]"),
              1u)
        << log;
    EXPECT_NE(log.find("accessors[4] min [0, 0, 0] max [1.5259e-05, 1.5259e-05, 0], data "
                       "[0, 0, 0] to [1, 1, 0])"),
              std::string::npos)
        << log;
    ASSERT_EQ(s.meshes.size(), 5u);
    EXPECT_EQ(s.meshes[1].bounds.hi.y, 2.0f);
    EXPECT_EQ(s.meshes[2].bounds.lo.x, 0.0f);
    EXPECT_NE(strict_error(path).find("3 POSITION accessor(s) have a min/max that disagrees"),
              std::string::npos);
}

// Index counts of 4 and 5 lose their last 1 and 2 indices; 2 indices make no triangle.
TEST(GltfMeshChecks, PartialAndEmptyPrimitivesAreOneWarningEach) {
    const ScratchDir dir;
    GltfBuilder b;
    const int pos = b.add(kTriangle, test::kFloat, "VEC3");
    std::vector<std::string> prims;
    for (const std::vector<uint16_t>& idx :
         {std::vector<uint16_t>{0, 1, 2, 0}, std::vector<uint16_t>{0, 1, 2, 0, 1},
          std::vector<uint16_t>{0, 1}})
        prims.push_back("{\"attributes\":{\"POSITION\":" + std::to_string(pos) + "},\"indices\":" +
                        std::to_string(b.add(idx, test::kUShort, "SCALAR")) + "}");
    const std::string path =
        b.write(dir, "partial.gltf", primitives_scene(prims), test::BufferStorage::DataUri);
    Scene s;
    const std::string log = warnings_of(path, &s);
    EXPECT_EQ(count(log, "warning: "), 2u) << log;
    EXPECT_EQ(count(log, path + ": meshes: 3 primitive(s) have an index count that is not a "
                                "multiple of 3; the last 1 or 2 indices are ignored "
                                "(meshes[0].primitives[0] has 4, meshes[0].primitives[1] has "
                                "5, meshes[0].primitives[2] has 2)\n"),
              1u)
        << log;
    EXPECT_EQ(count(log, path + ": meshes: 1 primitive(s) have no triangles; skipped "
                                "(meshes[0].primitives[2])\n"),
              1u)
        << log;
    EXPECT_EQ(s.meshes.size(), 2u);
}

// A 200 x 100 grid (40000 triangles) with normals and UVs: its vertex and index arrays are
// held once (28.3 bytes per triangle: 32 bytes for each of 20301 vertices, 12 for each
// triangle's indices, plus Embree's spare vertex), and Embree reads them in place.
TEST(GltfMeshChecks, LoadedMeshesAreHeldOnceAndSharedWithEmbree) {
    const ScratchDir dir;
    GltfBuilder b;
    const int cols = 200, rows = 100;
    std::vector<float> pos, nrm, uv;
    for (int j = 0; j <= rows; ++j)
        for (int i = 0; i <= cols; ++i) {
            pos.insert(pos.end(), {float(i), 0.01f * float((i * j) % 7), float(j)});
            nrm.insert(nrm.end(), {0, 1, 0});
            uv.insert(uv.end(), {float(i) / cols, float(j) / rows});
        }
    std::vector<uint32_t> idx;
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < cols; ++i) {
            const uint32_t a = uint32_t(j * (cols + 1) + i), c = a + cols + 1;
            idx.insert(idx.end(), {a, c, a + 1, a + 1, c, c + 1});
        }
    const std::string prim =
        "{\"attributes\":{\"POSITION\":" + std::to_string(b.add(pos, test::kFloat, "VEC3")) +
        ",\"NORMAL\":" + std::to_string(b.add(nrm, test::kFloat, "VEC3")) +
        ",\"TEXCOORD_0\":" + std::to_string(b.add(uv, test::kFloat, "VEC2")) +
        "},\"indices\":" + std::to_string(b.add(idx, test::kUInt, "SCALAR")) + "}";
    Scene s;
    const std::string log = warnings_of(
        b.write(dir, "grid.gltf", test::one_mesh_scene(prim), test::BufferStorage::ExternalBin),
        &s);
    EXPECT_EQ(log, "");
    ASSERT_EQ(s.meshes.size(), 1u);
    const size_t triangles = s.meshes[0].triangle_count();
    ASSERT_EQ(triangles, size_t(2 * cols * rows));
    const size_t exact = 32 * pos.size() / 3 + 12 * triangles;
    EXPECT_GE(mesh_memory_bytes(s), exact);
    EXPECT_LE(mesh_memory_bytes(s), exact + 64);
    const EmbreeAccel accel(s);
    EXPECT_EQ(accel.copied_bytes(), 0u);
}

// Draco-decoded positions (lossy) are not held to the file's bounds: encoders write the
// bounds of the values before quantisation. Their absence is still reported.
TEST(GltfMeshChecks, LossyPositionsAreNotHeldToTheirBounds) {
    tinygltf::Model model;
    model.accessors.resize(2);
    model.accessors[0].minValues = {0, 0, 0};
    model.accessors[0].maxValues = {1, 1, 1};
    const GltfContext ctx{model, "draco.glb"};
    const std::vector<Vec3> quantised = {{0, 0, 0}, {1.001f, 1, 1}};  // 1e-3 off
    for (const bool lossy : {true, false}) {
        MeshChecks checks(ctx);
        checks.check_position_bounds(0, quantised, lossy);
        checks.check_position_bounds(1, quantised, lossy);  // no bounds
        testing::internal::CaptureStderr();
        checks.report();
        const std::string log = testing::internal::GetCapturedStderr();
        EXPECT_EQ(count(log, "1 POSITION accessor(s) have no min/max"), 1u) << log;
        EXPECT_EQ(count(log, "disagrees with their data"), lossy ? 0u : 1u) << log;
    }
}

}  // namespace
}  // namespace penumbra
