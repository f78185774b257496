// Primitives to TriangleMeshes: buffer storage (data URI, external .bin, GLB), index
// types, strips and fans, generated flat normals, and the accessor features (strides,
// normalized integers, sparse, no bufferView, quantized positions).
#include <gtest/gtest.h>

#include "io/gltf/gltf_loader.h"
#include "support/gltf_builder.h"

namespace penumbra {
namespace {

using test::BufferStorage;
using test::GltfBuilder;
using test::ScratchDir;

// A unit quad in z = 0 as 4 vertices with +Z normals.
const std::vector<float> kQuad = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
const std::vector<float> kQuadNormals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};

Vec3 face_normal(const TriangleMesh& m, size_t t) {
    const Vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
               c = m.positions[m.indices[3 * t + 2]];
    return normalize(cross(b - a, c - a));
}

class BufferStorageTest : public ::testing::TestWithParam<BufferStorage> {};

TEST_P(BufferStorageTest, LoadsAQuad) {
    ScratchDir dir;
    GltfBuilder b;
    const int pos = b.add(kQuad, test::kFloat, "VEC3");
    const int nrm = b.add(kQuadNormals, test::kFloat, "VEC3");
    const int idx = b.add(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, test::kUShort, "SCALAR");
    const std::string prim = R"({"attributes": {"POSITION": )" + std::to_string(pos) +
                             R"(, "NORMAL": )" + std::to_string(nrm) + R"(}, "indices": )" +
                             std::to_string(idx) + "}";
    const char* name = GetParam() == BufferStorage::Glb ? "quad.glb" : "quad.gltf";
    const Scene s = load_gltf(b.write(dir, name, test::one_mesh_scene(prim), GetParam()));
    ASSERT_EQ(s.meshes.size(), 1u);
    const TriangleMesh& m = s.meshes[0];
    EXPECT_EQ(m.triangle_count(), 2u);
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
    EXPECT_EQ(m.positions[2].x, 1.0f);
    EXPECT_EQ(m.positions[2].y, 1.0f);
    EXPECT_EQ(m.normals[3].z, 1.0f);
    EXPECT_EQ(m.bounds.lo.x, 0.0f);
    EXPECT_EQ(m.bounds.hi.y, 1.0f);
    EXPECT_EQ(s.objects[0].meshes, std::vector<uint32_t>{0});
}

INSTANTIATE_TEST_SUITE_P(GltfMesh, BufferStorageTest,
                         ::testing::Values(BufferStorage::DataUri, BufferStorage::ExternalBin,
                                           BufferStorage::Glb));

// The same quad indexed with each index component type.
TEST(GltfMesh, IndexComponentTypes) {
    ScratchDir dir;
    GltfBuilder b;
    b.add(kQuad, test::kFloat, "VEC3");
    const int i8 = b.add(std::vector<uint8_t>{0, 1, 2, 0, 2, 3}, test::kUByte, "SCALAR");
    const int i16 = b.add(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, test::kUShort, "SCALAR");
    const int i32 = b.add(std::vector<uint32_t>{0, 1, 2, 0, 2, 3}, test::kUInt, "SCALAR");
    std::string prims;
    for (int idx : {i8, i16, i32})
        prims += std::string(prims.empty() ? "" : ",") +
                 R"({"attributes": {"POSITION": 0}, "indices": )" + std::to_string(idx) + "}";
    const Scene s =
        load_gltf(b.write(dir, "idx.gltf", test::one_mesh_scene(prims), BufferStorage::DataUri));
    ASSERT_EQ(s.meshes.size(), 3u);
    ASSERT_EQ(s.objects[0].meshes.size(), 3u);
    EXPECT_EQ(s.triangle_count(), 6u);
    // Without NORMAL, vertices are un-indexed; the triangles' corners are unchanged.
    for (const TriangleMesh& m : s.meshes) {
        ASSERT_EQ(m.positions.size(), 6u);
        EXPECT_EQ(m.positions[4].x, 1.0f);
        EXPECT_EQ(m.positions[4].y, 1.0f);
        EXPECT_EQ(m.positions[5].y, 1.0f);
        EXPECT_EQ(m.positions[5].x, 0.0f);
    }
}

TEST(GltfMesh, StripAndFanKeepWinding) {
    ScratchDir dir;
    GltfBuilder b;
    // A strip zig-zagging bottom, top, bottom, ... along +X (all its triangles face -Z
    // only if odd ones are flipped) and a fan around (0, 0) facing +Z.
    b.add(std::vector<float>{0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0, 2, 0, 0, 2, 1, 0}, test::kFloat,
          "VEC3");
    b.add(std::vector<uint16_t>{0, 1, 2, 3, 4, 5}, test::kUShort, "SCALAR");
    b.add(std::vector<float>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, -1, 0.5f, 0}, test::kFloat,
          "VEC3");
    const std::string prims = R"({"attributes": {"POSITION": 0}, "indices": 1, "mode": 5},
                                 {"attributes": {"POSITION": 2}, "mode": 6})";
    const Scene s =
        load_gltf(b.write(dir, "strip.gltf", test::one_mesh_scene(prims), BufferStorage::DataUri));
    ASSERT_EQ(s.meshes.size(), 2u);
    const TriangleMesh& strip = s.meshes[0];
    ASSERT_EQ(strip.triangle_count(), 4u);
    for (size_t t = 0; t < 4; ++t) EXPECT_NEAR(face_normal(strip, t).z, -1.0f, 1e-6f) << t;
    const TriangleMesh& fan = s.meshes[1];
    ASSERT_EQ(fan.triangle_count(), 3u);
    for (size_t t = 0; t < 3; ++t) {
        EXPECT_NEAR(face_normal(fan, t).z, 1.0f, 1e-6f) << t;
        EXPECT_EQ(fan.positions[fan.indices[3 * t]].x, 0.0f);  // every triangle has the hub
        EXPECT_EQ(fan.normals[fan.indices[3 * t]].z, 1.0f);    // flat normals
    }
}

TEST(GltfMesh, MissingNormalsAreFlat) {
    ScratchDir dir;
    GltfBuilder b;
    // Two triangles sharing an edge at a right angle, with shared (indexed) vertices.
    b.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}, test::kFloat, "VEC3");
    b.add(std::vector<uint8_t>{0, 1, 2, 0, 3, 1}, test::kUByte, "SCALAR");
    b.add(std::vector<float>{1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1}, test::kFloat, "VEC4");
    const std::string prim = R"({"attributes": {"POSITION": 0, "TANGENT": 2}, "indices": 1})";
    const Scene s =
        load_gltf(b.write(dir, "flat.gltf", test::one_mesh_scene(prim), BufferStorage::DataUri));
    const TriangleMesh& m = s.meshes[0];
    ASSERT_EQ(m.positions.size(), 6u);
    ASSERT_EQ(m.normals.size(), 6u);
    EXPECT_TRUE(m.tangents.empty());  // the spec: ignore tangents when normals are generated
    for (int v = 0; v < 3; ++v) EXPECT_EQ(m.normals[v].z, 1.0f);
    for (int v = 3; v < 6; ++v) EXPECT_EQ(m.normals[v].y, 1.0f);
}

// POSITION and TEXCOORD_0 interleaved with a 20-byte stride at an accessor offset;
// normalized u8 texture coordinates, u16 RGBA colours and normalized i8 normals.
TEST(GltfMesh, StridesAndNormalizedAttributes) {
    ScratchDir dir;
    GltfBuilder b;
    std::vector<uint8_t>& bytes = b.bytes();
    for (int v = 0; v < 3; ++v) {
        const float p[3] = {float(v == 1), float(v == 2), 0};
        const float uv[2] = {0.25f * float(v), 0.5f};
        bytes.insert(bytes.end(), reinterpret_cast<const uint8_t*>(p),
                     reinterpret_cast<const uint8_t*>(p) + 12);
        bytes.insert(bytes.end(), reinterpret_cast<const uint8_t*>(uv),
                     reinterpret_cast<const uint8_t*>(uv) + 8);
    }
    b.add_view(0, 60, 20);
    b.add_accessor(0, 0, test::kFloat, "VEC3", 3);   // 0: POSITION
    b.add_accessor(0, 12, test::kFloat, "VEC2", 3);  // 1: TEXCOORD_1
    b.add(std::vector<uint8_t>{0, 255, 255, 0, 51, 102}, test::kUByte, "VEC2",
          R"("normalized": true)");  // 2: TEXCOORD_0
    b.add(std::vector<uint16_t>{65535, 0, 0, 65535, 0, 65535, 0, 0, 0, 0, 65535, 32768},
          test::kUShort, "VEC4", R"("normalized": true)");  // 3: COLOR_0
    b.add(std::vector<int8_t>{0, 0, 127, 0, 0, 127, 0, 0, -128, 0}, test::kByte, "VEC3",
          R"("normalized": true)");  // 4: NORMAL (9 values used, 1 padding)
    const std::string prim = R"({"attributes": {"POSITION": 0, "TEXCOORD_1": 1,
        "TEXCOORD_0": 2, "COLOR_0": 3, "NORMAL": 4}})";
    const Scene s =
        load_gltf(b.write(dir, "stride.gltf", test::one_mesh_scene(prim), BufferStorage::DataUri));
    const TriangleMesh& m = s.meshes[0];
    EXPECT_EQ(m.positions[1].x, 1.0f);
    EXPECT_EQ(m.positions[2].y, 1.0f);
    EXPECT_FLOAT_EQ(m.uv1[2].x, 0.5f);
    EXPECT_FLOAT_EQ(m.uv1[2].y, 0.5f);
    EXPECT_FLOAT_EQ(m.uv0[0].y, 1.0f);
    EXPECT_FLOAT_EQ(m.uv0[2].x, 0.2f);
    EXPECT_FLOAT_EQ(m.colors[0].x, 1.0f);
    EXPECT_FLOAT_EQ(m.colors[2].w, 32768.0f / 65535.0f);
    EXPECT_FLOAT_EQ(m.normals[0].z, 1.0f);
    EXPECT_FLOAT_EQ(m.normals[2].z, -1.0f);  // -128 clamps to -1
}

// An accessor with no bufferView (zeros) plus sparse substitution, and a
// KHR_mesh_quantization position accessor of normalized shorts.
TEST(GltfMesh, SparseAndQuantizedAccessors) {
    ScratchDir dir;
    GltfBuilder b;
    b.add(std::vector<uint16_t>{1, 2}, test::kUShort, "SCALAR");        // 0: sparse indices
    b.add(std::vector<float>{5, 0, 0, 0, 7, 0}, test::kFloat, "VEC3");  // 1: sparse values
    b.add_accessor(-1, 0, test::kFloat, "VEC3", 3, R"("sparse": {"count": 2,
        "indices": {"bufferView": 0, "componentType": 5123},
        "values": {"bufferView": 1}})");                                // 2
    b.add(std::vector<int16_t>{0, 0, 0, 32767, 0, 0, 0, -32767, 0, 0}, test::kShort, "VEC3",
          R"("normalized": true)");  // 3
    const std::string members = R"("extensionsUsed": ["KHR_mesh_quantization"],
        "extensionsRequired": ["KHR_mesh_quantization"],)" +
                                test::one_mesh_scene(R"({"attributes": {"POSITION": 2}},
                                                        {"attributes": {"POSITION": 3}})");
    const Scene s = load_gltf(b.write(dir, "sparse.gltf", members, BufferStorage::DataUri));
    ASSERT_EQ(s.meshes.size(), 2u);
    const TriangleMesh& sparse = s.meshes[0];
    EXPECT_EQ(sparse.positions[0].x, 0.0f);
    EXPECT_EQ(sparse.positions[1].x, 5.0f);
    EXPECT_EQ(sparse.positions[2].y, 7.0f);
    const TriangleMesh& q = s.meshes[1];
    EXPECT_FLOAT_EQ(q.positions[1].x, 1.0f);
    EXPECT_FLOAT_EQ(q.positions[2].y, -1.0f);
}

TEST(GltfMesh, PointsAndLinesAreSkipped) {
    ScratchDir dir;
    GltfBuilder b;
    b.add(kQuad, test::kFloat, "VEC3");
    const std::string prims = R"({"attributes": {"POSITION": 0}, "mode": 0},
                                 {"attributes": {"POSITION": 0}, "mode": 1},
                                 {"attributes": {"POSITION": 0}, "mode": 4})";
    const Scene s =
        load_gltf(b.write(dir, "lines.gltf", test::one_mesh_scene(prims), BufferStorage::DataUri));
    EXPECT_EQ(s.meshes.size(), 1u);
    EXPECT_EQ(s.triangle_count(), 1u);  // 4 vertices as a list: one triangle, one left over
}

TEST(GltfMesh, SingleSidedEmitterWithNormalsAgainstItsWindingIsReported) {
    // The quad winds counter-clockwise seen from +Z; its normals say -Z.
    const std::vector<float> back_normals = {0, 0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1};
    ScratchDir dir;
    const auto warning_for = [&](const char* name, const std::string& material,
                                 const std::vector<float>& normals) {
        GltfBuilder b;
        b.add(kQuad, test::kFloat, "VEC3");
        b.add(normals, test::kFloat, "VEC3");
        b.add(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, test::kUShort, "SCALAR");
        const std::string members =
            R"("materials": [)" + material + "]," +
            test::one_mesh_scene(
                R"({"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "material": 0})");
        ::testing::internal::CaptureStderr();
        load_gltf(b.write(dir, name, members, BufferStorage::DataUri));
        return ::testing::internal::GetCapturedStderr().find(
                   "single-sided emitters whose normals point to their back faces") !=
               std::string::npos;
    };
    const std::string emitter = R"({"emissiveFactor": [1, 1, 1]})";
    EXPECT_TRUE(warning_for("backwards.gltf", emitter, back_normals));
    EXPECT_FALSE(warning_for("agreeing.gltf", emitter, kQuadNormals));
    EXPECT_FALSE(warning_for("double.gltf", R"({"emissiveFactor": [1, 1, 1], "doubleSided": true})",
                             back_normals));
    EXPECT_FALSE(warning_for("dark.gltf", "{}", back_normals));
}

}  // namespace
}  // namespace penumbra
