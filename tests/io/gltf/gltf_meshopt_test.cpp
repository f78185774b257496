// EXT_meshopt_compression: streams encoded here with meshoptimizer's own encoders and
// filters load back to the same geometry within each filter's quantisation; corrupt or
// oversized views fail naming the bufferView; gltfpack's pirate loads as its accessors say.
#include <gtest/gtest.h>
#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>

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

template <typename T>
std::vector<uint8_t> as_bytes(const std::vector<T>& v) {
    std::vector<uint8_t> out(v.size() * sizeof(T));
    std::memcpy(out.data(), v.data(), out.size());
    return out;
}

// Compressed streams in buffer 0 decoding into the fallback buffer 1, as gltfpack lays
// them out. `corrupt` may change a stream's compressed bytes before they are stored.
class MeshoptWriter {
public:
    // `raw`: count elements of `stride` bytes (indices: uint32 values, stored with `stride`
    // 2 or 4). Returns the bufferView index.
    int add(const std::vector<uint8_t>& raw, size_t count, size_t stride, const std::string& mode,
            const std::string& filter = "NONE", const std::string& count_override = "") {
        std::vector<uint8_t> enc;
        if (mode == "ATTRIBUTES") {
            enc.resize(meshopt_encodeVertexBufferBound(count, stride));
            enc.resize(
                meshopt_encodeVertexBuffer(enc.data(), enc.size(), raw.data(), count, stride));
        } else {
            const auto* idx = reinterpret_cast<const unsigned int*>(raw.data());
            const bool tri = mode == "TRIANGLES";
            enc.resize(tri ? meshopt_encodeIndexBufferBound(count, 1 << 16)
                           : meshopt_encodeIndexSequenceBound(count, 1 << 16));
            enc.resize(tri ? meshopt_encodeIndexBuffer(enc.data(), enc.size(), idx, count)
                           : meshopt_encodeIndexSequence(enc.data(), enc.size(), idx, count));
        }
        EXPECT_GT(enc.size(), 0u);
        if (corrupt) corrupt(enc);
        std::vector<uint8_t>& bin = b.bytes();
        while (bin.size() % 4) bin.push_back(0);
        const size_t at = bin.size();
        bin.insert(bin.end(), enc.begin(), enc.end());
        while (m_fallback % 4) ++m_fallback;
        std::string ext =
            "{\"buffer\":0,\"byteOffset\":" + std::to_string(at) +
            ",\"byteLength\":" + std::to_string(enc.size()) +
            ",\"byteStride\":" + std::to_string(stride) + ",\"mode\":\"" + mode +
            "\",\"count\":" + (count_override.empty() ? std::to_string(count) : count_override);
        if (filter != "NONE") ext += ",\"filter\":\"" + filter + "\"";
        std::string view = "{\"buffer\":1,\"byteOffset\":" + std::to_string(m_fallback) +
                           ",\"byteLength\":" + std::to_string(count * stride);
        if (mode == "ATTRIBUTES") view += ",\"byteStride\":" + std::to_string(stride);
        view += ",\"extensions\":{\"EXT_meshopt_compression\":" + ext + "}}}";
        m_fallback += count * stride;
        return b.add_view_json(view);
    }
    std::string write(const ScratchDir& dir, const char* name, const std::string& members,
                      BufferStorage storage, size_t fallback_length = 0) {
        b.add_buffer_json(
            "{\"byteLength\":" + std::to_string(fallback_length ? fallback_length : m_fallback) +
            ",\"extensions\":{\"EXT_meshopt_compression\":{\"fallback\":true}}}");
        const std::string ext =
            "\"extensionsUsed\":[\"EXT_meshopt_compression\","
            "\"KHR_mesh_quantization\"],\"extensionsRequired\":["
            "\"EXT_meshopt_compression\",\"KHR_mesh_quantization\"],";
        return b.write(dir, name, ext + members, storage);
    }
    GltfBuilder b;
    std::function<void(std::vector<uint8_t>&)> corrupt;

private:
    size_t m_fallback = 0;
};

// Filter inputs: 4 floats per vector.
std::vector<float> padded(const std::vector<float>& v3) {
    std::vector<float> out;
    for (size_t i = 0; i < v3.size(); i += 3)
        out.insert(out.end(), {v3[i], v3[i + 1], v3[i + 2], 0});
    return out;
}

// The grid with every stream kind: positions and uv1 plain floats, normals octahedral in
// bytes (8 bits), tangents octahedral in shorts (12 bits), uv0 exponential (15-bit
// mantissa), colours plain normalized bytes; primitive 0 indexed by a TRIANGLES stream
// (uint32), primitive 1 by an INDICES stream (uint16).
std::string grid_primitives(MeshoptWriter& w, const ReferenceGrid& g) {
    const size_t n = g.vertex_count(), ni = g.indices.size();
    std::vector<int8_t> nrm(n * 4);
    meshopt_encodeFilterOct(nrm.data(), n, 4, 8, padded(g.normals).data());
    std::vector<int16_t> tan(n * 4);
    meshopt_encodeFilterOct(tan.data(), n, 8, 12, g.tangents.data());
    std::vector<uint32_t> uv0(n * 2);
    meshopt_encodeFilterExp(uv0.data(), n, 8, 15, g.uv0.data());
    std::vector<uint8_t> col(n * 4);
    for (size_t i = 0; i < col.size(); ++i) col[i] = uint8_t(std::lround(g.colors[i] * 255));
    auto acc = [&](int view, int type, const char* t, const char* extra = "") {
        return std::to_string(w.b.add_accessor(view, 0, type, t, n, extra));
    };
    const std::string pos =
        acc(w.add(as_bytes(g.positions), n, 12, "ATTRIBUTES"), test::kFloat, "VEC3");
    const std::string nor = acc(w.add(as_bytes(nrm), n, 4, "ATTRIBUTES", "OCTAHEDRAL"), test::kByte,
                                "VEC3", "\"normalized\":true");
    const std::string tng = acc(w.add(as_bytes(tan), n, 8, "ATTRIBUTES", "OCTAHEDRAL"),
                                test::kShort, "VEC4", "\"normalized\":true");
    const std::string t0 =
        acc(w.add(as_bytes(uv0), n, 8, "ATTRIBUTES", "EXPONENTIAL"), test::kFloat, "VEC2");
    const std::string t1 = acc(w.add(as_bytes(g.uv1), n, 8, "ATTRIBUTES"), test::kFloat, "VEC2");
    const std::string c0 =
        acc(w.add(col, n, 4, "ATTRIBUTES"), test::kUByte, "VEC4", "\"normalized\":true");
    const int tri = w.b.add_accessor(w.add(as_bytes(g.indices), ni, 4, "TRIANGLES"), 0, test::kUInt,
                                     "SCALAR", ni);
    const int seq = w.b.add_accessor(w.add(as_bytes(g.indices), ni, 2, "INDICES"), 0, test::kUShort,
                                     "SCALAR", ni);
    const std::string attrs = "{\"POSITION\":" + pos + ",\"NORMAL\":" + nor +
                              ",\"TANGENT\":" + tng + ",\"TEXCOORD_0\":" + t0 +
                              ",\"TEXCOORD_1\":" + t1 + ",\"COLOR_0\":" + c0 + "}";
    return "{\"attributes\":" + attrs + ",\"indices\":" + std::to_string(tri) +
           "},{\"attributes\":" + attrs + ",\"indices\":" + std::to_string(seq) + "}";
}

class MeshoptRoundTrip : public ::testing::TestWithParam<BufferStorage> {};

TEST_P(MeshoptRoundTrip, SameGeometryWithinFilterQuantisation) {
    ScratchDir dir;
    const ReferenceGrid g = test::make_reference_grid();
    MeshoptWriter w;
    const std::string prims = grid_primitives(w, g);
    const bool glb = GetParam() == BufferStorage::Glb;
    const Scene s =
        load_gltf(w.write(dir, glb ? "m.glb" : "m.gltf", test::one_mesh_scene(prims), GetParam()));
    ASSERT_EQ(s.meshes.size(), 2u);
    // The codecs are lossless, the filters not. Octahedral in K bits: half a step,
    // 0.5 / (2^(K-1) - 1), on each octahedron coordinate, times at most 2 for the map's
    // stretch on both axes, then the output integers' rounding on three components:
    // (2 sqrt(2) + sqrt(3)) * 0.5 / (2^(K-1) - 1), 1.8e-2 for the 8-bit normals (a vector
    // distance) and 1.1e-3 for the 12-bit tangents (bounding each component). Exponential:
    // a 15-bit mantissa shared by (u, v) <= 1, 2^-15. Colours: the test's own rounding to
    // bytes, 0.5 / 255.
    test::GridTolerance tol;
    tol.position = 0;
    tol.uv1 = 0;
    tol.normal = 1.8e-2f;
    tol.tangent = 1.1e-3f;
    tol.uv0 = std::ldexp(1.0f, -15);
    tol.color = 0.5f / 255 + 1e-7f;
    for (const TriangleMesh& m : s.meshes) {
        const test::GridTolerance worst = test::expect_matches_grid(m, g, tol);
        RecordProperty("worst_normal", std::to_string(worst.normal));
        RecordProperty("worst_tangent", std::to_string(worst.tangent));
        RecordProperty("worst_uv0", std::to_string(worst.uv0));
        // The filters do lose something (a decoder that skipped them would be far off).
        EXPECT_GT(worst.normal, 0.0f);
        EXPECT_GT(worst.uv0, 0.0f);
    }
}

INSTANTIATE_TEST_SUITE_P(GltfMeshopt, MeshoptRoundTrip,
                         ::testing::Values(BufferStorage::Glb, BufferStorage::DataUri,
                                           BufferStorage::ExternalBin));

// QUATERNION (stride 8, 12 bits) on EXT_mesh_gpu_instancing rotations: each instance's
// x and y axes are those of its quaternion.
TEST(GltfMeshopt, QuaternionFilterRotations) {
    ScratchDir dir;
    MeshoptWriter w;
    const ReferenceGrid g = test::make_reference_grid(3);
    const int pos =
        w.b.add_accessor(w.add(as_bytes(g.positions), g.vertex_count(), 12, "ATTRIBUTES"), 0,
                         test::kFloat, "VEC3", g.vertex_count());
    const size_t count = 16;
    std::vector<float> q;
    for (size_t i = 0; i < count; ++i) {
        const float a = 0.7f * float(i) + 0.1f, b = 1.3f * float(i);  // angle, axis azimuth
        const Vec3 axis = normalize(Vec3{std::cos(b), std::sin(b), 0.5f});
        q.insert(q.end(), {axis.x * std::sin(a / 2), axis.y * std::sin(a / 2),
                           axis.z * std::sin(a / 2), std::cos(a / 2)});
    }
    std::vector<int16_t> enc(count * 4);
    meshopt_encodeFilterQuat(enc.data(), count, 8, 12, q.data());
    const int rot = w.b.add_accessor(w.add(as_bytes(enc), count, 8, "ATTRIBUTES", "QUATERNION"), 0,
                                     test::kShort, "VEC4", count, "\"normalized\":true");
    const std::string members =
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(pos) +
        "}}]}],\"nodes\":[{\"mesh\":0,\"extensions\":{\"EXT_mesh_gpu_instancing\":{"
        "\"attributes\":{\"ROTATION\":" +
        std::to_string(rot) + "}}}}],\"scenes\":[{\"nodes\":[0]}]";
    std::string path = w.write(dir, "q.glb", members, BufferStorage::Glb);
    const Scene s = load_gltf(path);
    ASSERT_EQ(s.instances.size(), count);
    // 12-bit components: |dq| <= 2 * 0.5 / (2^11 - 1) * sqrt(4) / sqrt(2), and a rotated
    // unit vector moves by at most 2 |dq| = 1.4e-3.
    float worst = 0;
    for (size_t i = 0; i < count; ++i) {
        const Vec3 u{q[4 * i], q[4 * i + 1], q[4 * i + 2]};
        const float qw = q[4 * i + 3];
        for (const Vec3 v : {Vec3{1, 0, 0}, Vec3{0, 1, 0}}) {
            const Vec3 t = 2.0f * cross(u, v);
            const Vec3 expected = v + qw * t + cross(u, t);
            worst = std::max(worst, length(s.instances[i].to_world.vector(v) - expected));
        }
    }
    RecordProperty("worst_rotated_axis", std::to_string(worst));
    EXPECT_LE(worst, 1.4e-3f);
    EXPECT_GT(worst, 0.0f);
}

void expect_error(const std::string& path, const std::string& expected) {
    try {
        load_gltf(path);
        ADD_FAILURE() << "no error, expected: " << expected;
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
}

std::string quad_file(const ScratchDir& dir, MeshoptWriter& w, const char* name,
                      const std::string& count_override = "", size_t fallback_length = 0) {
    const ReferenceGrid g = test::make_reference_grid(2);
    const int v = w.add(as_bytes(g.positions), 4, 12, "ATTRIBUTES", "NONE", count_override);
    const int pos = w.b.add_accessor(v, 0, test::kFloat, "VEC3", 4);
    return w.write(
        dir, name,
        test::one_mesh_scene("{\"attributes\":{\"POSITION\":" + std::to_string(pos) + "}}"),
        BufferStorage::Glb, fallback_length);
}

TEST(GltfMeshopt, CorruptStreamNamesTheBufferView) {
    ScratchDir dir;
    MeshoptWriter header;  // the vertex codec's header byte (0xA0 | version) broken
    header.corrupt = [](std::vector<uint8_t>& e) { e[0] = 0x00; };
    expect_error(quad_file(dir, header, "header.glb"),
                 "header.glb: bufferViews[0]: EXT_meshopt_compression: cannot decode");
    MeshoptWriter cut;  // the stream's tail cut off
    cut.corrupt = [](std::vector<uint8_t>& e) { e.resize(e.size() / 2); };
    expect_error(quad_file(dir, cut, "cut.glb"),
                 "cut.glb: bufferViews[0]: EXT_meshopt_compression: cannot decode");
}

TEST(GltfMeshopt, OversizedViewsFailBeforeAllocating) {
    ScratchDir dir;
    MeshoptWriter huge;  // 2 * 10^9 vertices (24 GB) claimed from a few dozen bytes
    expect_error(quad_file(dir, huge, "huge.glb", "2000000000"),
                 "bufferViews[0]: EXT_meshopt_compression: 2000000000 elements of 12 bytes "
                 "cannot come from");
    MeshoptWriter small;  // the fallback buffer declared shorter than its view
    expect_error(quad_file(dir, small, "small.glb", "", 40),
                 "past the fallback buffer's byteLength 40");
}

// pirate.glb (gltfpack, EXT_meshopt_compression + KHR_mesh_quantization): 5010 triangles,
// POSITION min [0, 0, 0] and max [13081, 16383, 3915] (unsigned shorts, exact), normals
// through OCTAHEDRAL, indices through TRIANGLES.
TEST(GltfMeshopt, PirateMatchesItsAccessors) {
    const Scene s = load_gltf(test::shared_path("scenes/wild/Pirate/pirate.glb"));
    ASSERT_EQ(s.meshes.size(), 1u);
    const TriangleMesh& m = s.meshes[0];
    EXPECT_EQ(m.triangle_count(), 5010u);
    EXPECT_EQ(m.bounds.lo, (Vec3{0, 0, 0}));
    EXPECT_EQ(m.bounds.hi, (Vec3{13081, 16383, 3915}));
    // Decoded normals agree with the surface: the mean cosine to each triangle's face
    // normal (a skipped or wrong filter gives about 0).
    double mean = 0;
    for (size_t t = 0; t < m.triangle_count(); ++t) {
        const uint32_t a = m.indices[3 * t], b = m.indices[3 * t + 1], c = m.indices[3 * t + 2];
        const Vec3 f = cross(m.positions[b] - m.positions[a], m.positions[c] - m.positions[a]);
        if (length(f) == 0) continue;
        mean += dot(normalize(f), normalize(m.normals[a] + m.normals[b] + m.normals[c]));
    }
    mean /= double(m.triangle_count());
    RecordProperty("mean_normal_cosine", std::to_string(mean));
    EXPECT_GT(mean, 0.9);
}

}  // namespace
}  // namespace penumbra
