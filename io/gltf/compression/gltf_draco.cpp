// KHR_draco_mesh_compression through libdraco (KhronosGroup/glTF, extensions/2.0/Khronos/
// KHR_draco_mesh_compression): the extension's bufferView is one Draco mesh whose
// attributes, by unique id, become the primitive's accessors, converted to the accessor's
// componentType as the JSON declares it. Draco dequantises (positions, texture
// coordinates, normals) while decoding; morph targets are never compressed (the spec).
#include "io/gltf/compression/gltf_draco.h"

#include <draco/compression/decode.h>

#include <cstring>
#include <map>
#include <memory>

#include "core/error.h"
#include "io/gltf/gltf_accessor.h"

namespace penumbra {

namespace {

template <typename T>
bool convert(const draco::PointAttribute& att, uint32_t points, int n, std::vector<uint8_t>& out) {
    const size_t begin = out.size();
    out.resize(begin + size_t(points) * size_t(n) * sizeof(T));
    T value[4];
    for (uint32_t i = 0; i < points; ++i) {
        if (!att.ConvertValue<T>(att.mapped_index(draco::PointIndex(i)), int8_t(n), value))
            return false;
        std::memcpy(out.data() + begin + size_t(i) * size_t(n) * sizeof(T), value,
                    size_t(n) * sizeof(T));
    }
    return true;
}

// Appends `points` values of `att` as `component_type` (glTF's enum); false when the type
// is not a vertex attribute type or a value does not fit it.
bool append_attribute(const draco::PointAttribute& att, uint32_t points, int n, int component_type,
                      std::vector<uint8_t>& out) {
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return convert<float>(att, points, n, out);
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            return convert<int8_t>(att, points, n, out);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return convert<uint8_t>(att, points, n, out);
        case TINYGLTF_COMPONENT_TYPE_SHORT:
            return convert<int16_t>(att, points, n, out);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return convert<uint16_t>(att, points, n, out);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            return convert<uint32_t>(att, points, n, out);
        default:
            return false;
    }
}

template <typename T>
void append_indices(const draco::Mesh& mesh, std::vector<uint8_t>& out) {
    const size_t begin = out.size();
    out.resize(begin + size_t(mesh.num_faces()) * 3 * sizeof(T));
    for (uint32_t f = 0; f < mesh.num_faces(); ++f)
        for (int k = 0; k < 3; ++k) {
            const T index = T(mesh.face(draco::FaceIndex(f))[k].value());
            std::memcpy(out.data() + begin + (size_t(f) * 3 + size_t(k)) * sizeof(T), &index,
                        sizeof(T));
        }
}

// The decoded bytes, gathered for one new buffer, and the Draco bufferView that filled each
// accessor.
struct DecodeState {
    tinygltf::Model& model;
    int out_buffer;
    std::vector<uint8_t> out;
    std::map<int, int> decoded_from;  // accessor -> Draco bufferView that filled it
};

// One compressed primitive: its element path (prefixing every message), its Draco
// bufferView and the decoded mesh.
struct DracoPrimitive {
    std::string where;
    int source = -1;
    std::unique_ptr<draco::Mesh> mesh;

    [[noreturn]] void fail(const std::string& problem) const {
        throw SceneError(where + ": " + problem);
    }
};

// Decodes the Draco mesh in bufferViews[d.source] into d.mesh.
void decode_mesh(const tinygltf::Model& model, DracoPrimitive& d) {
    if (d.source < 0 || size_t(d.source) >= model.bufferViews.size())
        d.fail("bufferView index " + std::to_string(d.source) + " out of range");
    const tinygltf::BufferView& view = model.bufferViews[size_t(d.source)];
    if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size() ||
        view.byteOffset > model.buffers[size_t(view.buffer)].data.size() ||
        view.byteLength > model.buffers[size_t(view.buffer)].data.size() - view.byteOffset)
        d.fail("bufferViews[" + std::to_string(d.source) + "] lies outside its buffer");

    draco::DecoderBuffer bytes;
    bytes.Init(reinterpret_cast<const char*>(model.buffers[size_t(view.buffer)].data.data() +
                                             view.byteOffset),
               view.byteLength);
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&bytes);
    if (!decoded.ok()) d.fail("cannot decode (" + decoded.status().error_msg_string() + ")");
    d.mesh = std::move(decoded).value();
}

// Each accessor once, into its own bufferView of the new buffer: true when this primitive
// fills `accessor`, false when the same Draco bufferView already did.
bool claim(DecodeState& state, const DracoPrimitive& d, int accessor, const std::string& semantic,
           uint32_t count) {
    if (accessor < 0 || size_t(accessor) >= state.model.accessors.size())
        d.fail(semantic + " accessor index " + std::to_string(accessor) + " out of range");
    const auto seen = state.decoded_from.find(accessor);
    if (seen != state.decoded_from.end()) {
        if (seen->second != d.source)
            d.fail(semantic + " accessor " + std::to_string(accessor) +
                   " is decoded by two Draco primitives");
        return false;
    }
    if (state.model.accessors[size_t(accessor)].count != count)
        d.fail(semantic + " accessor " + std::to_string(accessor) + " declares " +
               std::to_string(state.model.accessors[size_t(accessor)].count) +
               " elements, the Draco mesh has " + std::to_string(count));
    state.decoded_from[accessor] = d.source;
    while (state.out.size() % 4 != 0) state.out.push_back(0);
    return true;
}

// Points `accessor` at the bytes appended since `begin`.
void finish(DecodeState& state, int accessor, size_t begin) {
    tinygltf::BufferView v;
    v.buffer = state.out_buffer;
    v.byteOffset = begin;
    v.byteLength = state.out.size() - begin;
    state.model.bufferViews.push_back(v);
    tinygltf::Accessor& a = state.model.accessors[size_t(accessor)];
    a.bufferView = int(state.model.bufferViews.size()) - 1;
    a.byteOffset = 0;
    a.sparse = {};
}

void write_indices(DecodeState& state, const tinygltf::Primitive& prim, const DracoPrimitive& d) {
    const draco::Mesh& mesh = *d.mesh;
    const uint32_t points = mesh.num_points();
    if (prim.indices < 0 || !claim(state, d, prim.indices, "indices", mesh.num_faces() * 3)) return;
    std::vector<uint8_t>& out = state.out;
    const size_t begin = out.size();
    switch (state.model.accessors[size_t(prim.indices)].componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            if (points > 256)
                d.fail("indices: " + std::to_string(points) +
                       " points need "
                       "more than unsigned byte indices");
            append_indices<uint8_t>(mesh, out);
            break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            if (points > 65536)
                d.fail("indices: " + std::to_string(points) +
                       " points "
                       "need more than unsigned short indices");
            append_indices<uint16_t>(mesh, out);
            break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            append_indices<uint32_t>(mesh, out);
            break;
        default:
            d.fail("indices accessor has no unsigned integer componentType");
    }
    finish(state, prim.indices, begin);
}

// The extension's attributes map names the primitive's attributes to Draco unique ids.
void write_attributes(DecodeState& state, const tinygltf::Primitive& prim,
                      const tinygltf::Value& attributes, const DracoPrimitive& d) {
    const uint32_t points = d.mesh->num_points();
    for (const std::string& name : attributes.Keys()) {
        const auto target = prim.attributes.find(name);
        if (target == prim.attributes.end())
            d.fail("attribute " + name + " is not among the primitive's attributes");
        if (!attributes.Get(name).IsNumber())
            d.fail("attribute " + name + ": the Draco id must be a number");
        const int id = attributes.Get(name).GetNumberAsInt();
        const draco::PointAttribute* att = d.mesh->GetAttributeByUniqueId(uint32_t(id));
        if (!att) d.fail("attribute " + name + ": the Draco mesh has no id " + std::to_string(id));
        if (!claim(state, d, target->second, name, points)) continue;
        const tinygltf::Accessor& a = state.model.accessors[size_t(target->second)];
        // Matrices are no vertex attributes: 0 fails below.
        const int n = component_count(a.type) <= 4 ? component_count(a.type) : 0;
        if (n == 0 || att->num_components() != n)
            d.fail("attribute " + name + ": the accessor has " + std::to_string(n) +
                   " components, Draco id " + std::to_string(id) + " has " +
                   std::to_string(int(att->num_components())));
        const size_t begin = state.out.size();
        if (!append_attribute(*att, points, n, a.componentType, state.out))
            d.fail("attribute " + name +
                   ": Draco's values do not convert to the "
                   "accessor's componentType " +
                   std::to_string(a.componentType));
        finish(state, target->second, begin);
    }
}

void decode_primitive(DecodeState& state, const tinygltf::Primitive& prim,
                      const tinygltf::Value& ext, std::string where) {
    DracoPrimitive d;
    d.where = std::move(where);
    if (!ext.IsObject() || !ext.Get("bufferView").IsNumber() || !ext.Get("attributes").IsObject())
        d.fail("bufferView (a number) and attributes (an object) must be given");
    // Only triangle lists: Draco's point clouds are no surfaces, and the
    // extension allows no strips or fans.
    if (prim.mode != TINYGLTF_MODE_TRIANGLES) return;
    d.source = ext.Get("bufferView").GetNumberAsInt();
    decode_mesh(state.model, d);
    write_indices(state, prim, d);
    write_attributes(state, prim, ext.Get("attributes"), d);
}

}  // namespace

void decode_draco(tinygltf::Model& model, const std::string& file) {
    DecodeState state{model, int(model.buffers.size()), {}, {}};
    for (size_t m = 0; m < model.meshes.size(); ++m)
        for (size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
            const tinygltf::Primitive& prim = model.meshes[m].primitives[p];
            const auto found = prim.extensions.find("KHR_draco_mesh_compression");
            if (found == prim.extensions.end()) continue;
            decode_primitive(state, prim, found->second,
                             file + ": meshes[" + std::to_string(m) + "].primitives[" +
                                 std::to_string(p) + "]: KHR_draco_mesh_compression");
        }

    if (state.decoded_from.empty()) return;
    tinygltf::Buffer buffer;
    buffer.name = "KHR_draco_mesh_compression (decoded)";
    buffer.data = std::move(state.out);
    model.buffers.push_back(std::move(buffer));
}

}  // namespace penumbra
