// KHR_draco_mesh_compression: meshes encoded here with libdraco's own encoder load back
// to the same geometry within the quantisation error; corrupt streams and bad references
// fail naming the primitive; the Sketchfab chess board loads with its declared counts.
#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "io/gltf/gltf_loader.h"
#include "support/gltf_builder.h"
#include "support/paths.h"
#include "support/statistics/reference_grid.h"

namespace penumbra {
namespace {

using test::BufferStorage;
using test::GltfBuilder;
using test::ReferenceGrid;
using test::ScratchDir;

constexpr int kPositionBits = 14, kNormalBits = 10, kTexBits = 12, kColorBits = 10,
              kGenericBits = 12;

struct DracoFile {
    std::vector<uint8_t> bytes;
    int num_points = 0, num_faces = 0;
    int position = -1, normal = -1, uv0 = -1, uv1 = -1, tangent = -1, color = -1;  // unique ids
};

template <int N>
void set_face(draco::TriangleSoupMeshBuilder& b, int att, int face, const std::vector<float>& v,
              const ReferenceGrid& g) {
    const uint32_t* c = &g.indices[3 * size_t(face)];
    b.SetAttributeValuesForFace(att, draco::FaceIndex(uint32_t(face)), &v[N * c[0]], &v[N * c[1]],
                                &v[N * c[2]]);
}

// The grid as one Draco mesh, quantised as gltf-transform's defaults do (positions 14 bits,
// normals 10, texture coordinates 12, colours 10, generic 12); TANGENT is GENERIC.
DracoFile encode(const ReferenceGrid& g, int method) {
    draco::TriangleSoupMeshBuilder b;
    const int faces = int(g.indices.size() / 3);
    b.Start(faces);
    using T = draco::GeometryAttribute;
    const int pos = b.AddAttribute(T::POSITION, 3, draco::DT_FLOAT32);
    const int nrm = b.AddAttribute(T::NORMAL, 3, draco::DT_FLOAT32);
    const int uv0 = b.AddAttribute(T::TEX_COORD, 2, draco::DT_FLOAT32);
    const int uv1 = b.AddAttribute(T::TEX_COORD, 2, draco::DT_FLOAT32);
    const int tan = b.AddAttribute(T::GENERIC, 4, draco::DT_FLOAT32);
    const int col = b.AddAttribute(T::COLOR, 4, draco::DT_FLOAT32);
    for (int f = 0; f < faces; ++f) {
        set_face<3>(b, pos, f, g.positions, g);
        set_face<3>(b, nrm, f, g.normals, g);
        set_face<2>(b, uv0, f, g.uv0, g);
        set_face<2>(b, uv1, f, g.uv1, g);
        set_face<4>(b, tan, f, g.tangents, g);
        set_face<4>(b, col, f, g.colors, g);
    }
    std::unique_ptr<draco::Mesh> mesh = b.Finalize();
    EXPECT_TRUE(mesh);
    draco::Encoder enc;
    enc.SetAttributeQuantization(T::POSITION, kPositionBits);
    enc.SetAttributeQuantization(T::NORMAL, kNormalBits);
    enc.SetAttributeQuantization(T::TEX_COORD, kTexBits);
    enc.SetAttributeQuantization(T::COLOR, kColorBits);
    enc.SetAttributeQuantization(T::GENERIC, kGenericBits);
    enc.SetEncodingMethod(method);
    draco::EncoderBuffer out;
    const draco::Status st = enc.EncodeMeshToBuffer(*mesh, &out);
    EXPECT_TRUE(st.ok()) << st.error_msg_string();
    DracoFile file;
    file.bytes.assign(out.data(), out.data() + out.size());
    file.num_points = int(mesh->num_points());
    file.num_faces = int(mesh->num_faces());
    file.position = int(mesh->attribute(pos)->unique_id());
    file.normal = int(mesh->attribute(nrm)->unique_id());
    file.uv0 = int(mesh->attribute(uv0)->unique_id());
    file.uv1 = int(mesh->attribute(uv1)->unique_id());
    file.tangent = int(mesh->attribute(tan)->unique_id());
    file.color = int(mesh->attribute(col)->unique_id());
    return file;
}

// A glTF file whose only primitive is `d`, with accessors without bufferViews as
// gltf-transform writes them; `index_type` is the indices' componentType.
std::string write_draco(const ScratchDir& dir, const char* name, const DracoFile& d,
                        BufferStorage storage, int index_type = test::kUInt) {
    GltfBuilder b;
    b.bytes() = d.bytes;
    b.add_view(0, d.bytes.size());
    const size_t n = size_t(d.num_points);
    const int idx = b.add_accessor(-1, 0, index_type, "SCALAR", size_t(d.num_faces) * 3);
    const int pos = b.add_accessor(-1, 0, test::kFloat, "VEC3", n);
    const int nrm = b.add_accessor(-1, 0, test::kFloat, "VEC3", n);
    const int uv0 = b.add_accessor(-1, 0, test::kFloat, "VEC2", n);
    const int uv1 = b.add_accessor(-1, 0, test::kFloat, "VEC2", n);
    const int tan = b.add_accessor(-1, 0, test::kFloat, "VEC4", n);
    const int col = b.add_accessor(-1, 0, test::kFloat, "VEC4", n);
    auto pair = [](const char* k, int v) {
        return "\"" + std::string(k) + "\":" + std::to_string(v);
    };
    const std::string prim =
        "{\"attributes\":{" + pair("POSITION", pos) + "," + pair("NORMAL", nrm) + "," +
        pair("TEXCOORD_0", uv0) + "," + pair("TEXCOORD_1", uv1) + "," + pair("TANGENT", tan) + "," +
        pair("COLOR_0", col) + "}," + pair("indices", idx) +
        ",\"extensions\":{\"KHR_draco_mesh_compression\":{\"bufferView\":0,\"attributes\":{" +
        pair("POSITION", d.position) + "," + pair("NORMAL", d.normal) + "," +
        pair("TEXCOORD_0", d.uv0) + "," + pair("TEXCOORD_1", d.uv1) + "," +
        pair("TANGENT", d.tangent) + "," + pair("COLOR_0", d.color) + "}}}}";
    const std::string ext =
        "\"extensionsUsed\":[\"KHR_draco_mesh_compression\"],"
        "\"extensionsRequired\":[\"KHR_draco_mesh_compression\"],";
    return b.write(dir, name, ext + test::one_mesh_scene(prim), storage);
}

// Half a quantisation step of a `bits`-bit grid over `range`, with 1% for float rounding.
float half_step(float range, int bits) { return 0.505f * range / float((1 << bits) - 1); }

struct RoundTripCase {
    BufferStorage storage;
    int method;  // draco::MESH_SEQUENTIAL_ENCODING or MESH_EDGEBREAKER_ENCODING
};

class DracoRoundTrip : public ::testing::TestWithParam<RoundTripCase> {};

TEST_P(DracoRoundTrip, SameGeometryWithinQuantisation) {
    ScratchDir dir;
    const ReferenceGrid g = test::make_reference_grid();
    const DracoFile d = encode(g, GetParam().method);
    const bool glb = GetParam().storage == BufferStorage::Glb;
    const Scene s = load_gltf(write_draco(dir, glb ? "d.glb" : "d.gltf", d, GetParam().storage));
    ASSERT_EQ(s.meshes.size(), 1u);
    // Draco quantises each attribute over the cube of its largest extent: positions span
    // 2 (x, y in [-1, 1]), uv0 0.9, uv1 2, tangents 2, colours 1. Octahedral normals in 10
    // bits: half a step (1 / 1023) on each octahedron coordinate, times at most 2 for the
    // map's stretch on both axes, moves a unit vector by <= 2 sqrt(2) / 1023 = 2.8e-3.
    test::GridTolerance tol;
    tol.position = half_step(2, kPositionBits);
    tol.normal = 2.8e-3f;
    tol.uv0 = half_step(0.9f, kTexBits);
    tol.uv1 = half_step(2, kTexBits);
    tol.tangent = half_step(2, kGenericBits);
    tol.color = half_step(1, kColorBits);
    const test::GridTolerance worst = test::expect_matches_grid(s.meshes[0], g, tol);
    RecordProperty("worst_position", std::to_string(worst.position));
    RecordProperty("worst_normal", std::to_string(worst.normal));
    RecordProperty("worst_uv0", std::to_string(worst.uv0));
    RecordProperty("worst_tangent", std::to_string(worst.tangent));
    RecordProperty("worst_color", std::to_string(worst.color));
    // Quantisation is really there (so this test sees a decoder that skips the
    // dequantisation: errors would be whole ranges, not fractions of a step).
    EXPECT_GT(worst.position, 0.0f);
}

INSTANTIATE_TEST_SUITE_P(
    GltfDraco, DracoRoundTrip,
    ::testing::Values(RoundTripCase{BufferStorage::Glb, draco::MESH_EDGEBREAKER_ENCODING},
                      RoundTripCase{BufferStorage::DataUri, draco::MESH_EDGEBREAKER_ENCODING},
                      RoundTripCase{BufferStorage::ExternalBin, draco::MESH_SEQUENTIAL_ENCODING}));

TEST(GltfDraco, UnsignedShortIndices) {
    ScratchDir dir;
    const ReferenceGrid g = test::make_reference_grid(5);
    const DracoFile d = encode(g, draco::MESH_EDGEBREAKER_ENCODING);
    const Scene s = load_gltf(write_draco(dir, "d.glb", d, BufferStorage::Glb, test::kUShort));
    ASSERT_EQ(s.meshes.size(), 1u);
    EXPECT_EQ(s.meshes[0].triangle_count(), 32u);
    for (uint32_t i : s.meshes[0].indices) EXPECT_LT(i, s.meshes[0].positions.size());
}

// Integer attributes keep their values: TEXCOORD_0 as normalized unsigned shorts and
// COLOR_0 as normalized unsigned bytes in both Draco and the accessors (the
// KHR_mesh_quantization and JOINTS_n / WEIGHTS_n path: no float in between).
TEST(GltfDraco, IntegerAttributesExact) {
    ScratchDir dir;
    const ReferenceGrid g = test::make_reference_grid(5);
    const size_t nv = g.vertex_count();
    std::vector<uint16_t> uv(nv * 2);
    std::vector<uint8_t> col(nv * 4);
    for (size_t i = 0; i < uv.size(); ++i) uv[i] = uint16_t(std::lround(g.uv0[i] * 65535));
    for (size_t i = 0; i < col.size(); ++i) col[i] = uint8_t(std::lround(g.colors[i] * 255));
    draco::TriangleSoupMeshBuilder b;
    const int faces = int(g.indices.size() / 3);
    b.Start(faces);
    using T = draco::GeometryAttribute;
    const int pos = b.AddAttribute(T::POSITION, 3, draco::DT_FLOAT32);
    const int tex = b.AddAttribute(T::TEX_COORD, 2, draco::DT_UINT16);
    const int rgba = b.AddAttribute(T::COLOR, 4, draco::DT_UINT8);
    for (int f = 0; f < faces; ++f) {
        const uint32_t* c = &g.indices[3 * size_t(f)];
        const draco::FaceIndex fi{uint32_t(f)};
        b.SetAttributeValuesForFace(pos, fi, &g.positions[3 * c[0]], &g.positions[3 * c[1]],
                                    &g.positions[3 * c[2]]);
        b.SetAttributeValuesForFace(tex, fi, &uv[2 * c[0]], &uv[2 * c[1]], &uv[2 * c[2]]);
        b.SetAttributeValuesForFace(rgba, fi, &col[4 * c[0]], &col[4 * c[1]], &col[4 * c[2]]);
    }
    std::unique_ptr<draco::Mesh> mesh = b.Finalize();
    ASSERT_TRUE(mesh);
    draco::Encoder enc;
    enc.SetAttributeQuantization(T::POSITION, kPositionBits);
    draco::EncoderBuffer out;
    ASSERT_TRUE(enc.EncodeMeshToBuffer(*mesh, &out).ok());

    GltfBuilder gb;
    gb.bytes().assign(out.data(), out.data() + out.size());
    gb.add_view(0, out.size());
    const size_t n = mesh->num_points();
    const int idx = gb.add_accessor(-1, 0, test::kUInt, "SCALAR", mesh->num_faces() * 3);
    const int a_pos = gb.add_accessor(-1, 0, test::kFloat, "VEC3", n);
    const int a_tex = gb.add_accessor(-1, 0, test::kUShort, "VEC2", n, "\"normalized\":true");
    const int a_col = gb.add_accessor(-1, 0, test::kUByte, "VEC4", n, "\"normalized\":true");
    auto id = [&](int att) { return std::to_string(mesh->attribute(att)->unique_id()); };
    const std::string prim =
        "{\"attributes\":{\"POSITION\":" + std::to_string(a_pos) +
        ",\"TEXCOORD_0\":" + std::to_string(a_tex) + ",\"COLOR_0\":" + std::to_string(a_col) +
        "},\"indices\":" + std::to_string(idx) +
        ",\"extensions\":{\"KHR_draco_mesh_compression\":{\"bufferView\":0,\"attributes\":{"
        "\"POSITION\":" +
        id(pos) + ",\"TEXCOORD_0\":" + id(tex) + ",\"COLOR_0\":" + id(rgba) + "}}}}";
    const std::string ext =
        "\"extensionsUsed\":[\"KHR_draco_mesh_compression\"],"
        "\"extensionsRequired\":[\"KHR_draco_mesh_compression\"],";
    const Scene s =
        load_gltf(gb.write(dir, "int.glb", ext + test::one_mesh_scene(prim), BufferStorage::Glb));
    ASSERT_EQ(s.meshes.size(), 1u);
    const TriangleMesh& m = s.meshes[0];
    ASSERT_EQ(m.uv0.size(), m.positions.size());
    ASSERT_EQ(m.colors.size(), m.positions.size());
    for (size_t v = 0; v < m.positions.size(); ++v) {
        size_t r = 0;  // the reference vertex nearest to this one (positions are quantised)
        for (size_t q = 1; q < nv; ++q)
            if (length(m.positions[v] -
                       Vec3{g.positions[3 * q], g.positions[3 * q + 1], g.positions[3 * q + 2]}) <
                length(m.positions[v] -
                       Vec3{g.positions[3 * r], g.positions[3 * r + 1], g.positions[3 * r + 2]}))
                r = q;
        for (int a = 0; a < 2; ++a) EXPECT_EQ(m.uv0[v][a], float(uv[2 * r + size_t(a)]) / 65535);
        for (int a = 0; a < 4; ++a)
            EXPECT_EQ(m.colors[v][a], float(col[4 * r + size_t(a)]) / 255) << v << " " << a;
    }
}

void expect_error(const std::string& path, const std::string& expected) {
    try {
        load_gltf(path);
        ADD_FAILURE() << "no error, expected: " << expected;
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
}

TEST(GltfDraco, CorruptStreamNamesThePrimitive) {
    ScratchDir dir;
    const ReferenceGrid g = test::make_reference_grid();
    const std::string where = "meshes[0].primitives[0]: KHR_draco_mesh_compression: cannot decode";
    DracoFile d = encode(g, draco::MESH_EDGEBREAKER_ENCODING);
    DracoFile garbage = d;  // header overwritten: not a Draco stream
    for (size_t i = 0; i < 8; ++i) garbage.bytes[i] = 0xFF;
    expect_error(write_draco(dir, "garbage.glb", garbage, BufferStorage::Glb),
                 "garbage.glb: " + where);
    DracoFile cut = d;  // valid header, the connectivity and attributes cut off
    cut.bytes.resize(cut.bytes.size() / 3);
    expect_error(write_draco(dir, "cut.glb", cut, BufferStorage::Glb), "cut.glb: " + where);
}

TEST(GltfDraco, CountMismatchAndMissingIdFail) {
    ScratchDir dir;
    const ReferenceGrid g = test::make_reference_grid();
    DracoFile d = encode(g, draco::MESH_EDGEBREAKER_ENCODING);
    DracoFile fewer = d;
    fewer.num_points -= 1;  // the accessors declare one vertex less than Draco decodes
    expect_error(write_draco(dir, "count.glb", fewer, BufferStorage::Glb),
                 "declares " + std::to_string(fewer.num_points) +
                     " elements, the Draco mesh "
                     "has " +
                     std::to_string(d.num_points));
    expect_error(write_draco(dir, "count.glb", fewer, BufferStorage::Glb),
                 "count.glb: meshes[0].primitives[0]: KHR_draco_mesh_compression: ");
    DracoFile missing = d;
    missing.color = 99;
    expect_error(write_draco(dir, "id.glb", missing, BufferStorage::Glb),
                 "KHR_draco_mesh_compression: attribute COLOR_0: the Draco mesh has no id 99");
}

// chess-board.glb (Sketchfab via gltf-transform): 8 Draco primitives, the first five with
// TANGENT. Counts and bounds are what its accessors declare (indices count / 3; POSITION
// min/max, of the values before quantisation).
TEST(GltfDraco, ChessBoardMatchesItsAccessors) {
    const Scene s = load_gltf(test::shared_path("scenes/wild/ChessBoard/chess-board.glb"));
    struct Expected {
        size_t triangles;
        Vec3 lo, hi;
    };
    const Expected expected[] = {
        {117152, {-136.49016f, -136.49016f, -1.3464184f}, {136.49016f, 136.49016f, 12.515533f}},
        {13520, {-123.63547f, -132.45793f, -1.3464184f}, {132.45793f, 130.02608f, 11.350415f}},
        {8896, {36.747814f, -75.847328f, 6.5212069f}, {76.113152f, 76.445061f, 37.068928f}},
        {13850, {-157.49115f, -75.445190f, -0.13115521f}, {75.110962f, 76.383041f, 42.243607f}},
        {1342, {60.902710f, 22.144901f, 6.5282745f}, {74.664566f, 35.686127f, 41.156200f}},
        {8896, {-77.204987f, -35.358639f, 6.5212069f}, {20.947731f, 75.189499f, 37.068928f}},
        {13850, {-76.202881f, -76.511765f, -0.26350594f}, {179.56969f, 76.443275f, 42.243607f}},
        {1342, {21.963757f, 3.0973060f, 6.5282745f}, {35.844128f, 16.755152f, 41.156200f}}};
    ASSERT_EQ(s.meshes.size(), 8u);
    EXPECT_EQ(s.triangle_count(), 178848u);
    for (size_t i = 0; i < 8; ++i) {
        const TriangleMesh& m = s.meshes[i];
        EXPECT_EQ(m.triangle_count(), expected[i].triangles) << i;
        EXPECT_EQ(m.uv0.size(), m.positions.size()) << i;
        EXPECT_EQ(m.tangents.size(), i < 5 ? m.positions.size() : 0u) << i;
        // Min/max are of the values before quantisation: the decoded extremes lie within
        // half a step of gltf-transform's default 14-bit grid over the primitive's largest
        // extent (0.008 for the board; measured up to 0.0076).
        const Vec3 extent = expected[i].hi - expected[i].lo;
        const float tol = half_step(std::max({extent.x, extent.y, extent.z}), kPositionBits);
        for (int a = 0; a < 3; ++a) {
            EXPECT_NEAR(m.bounds.lo[a], expected[i].lo[a], tol) << i << " axis " << a;
            EXPECT_NEAR(m.bounds.hi[a], expected[i].hi[a], tol) << i << " axis " << a;
        }
    }
}

}  // namespace
}  // namespace penumbra
