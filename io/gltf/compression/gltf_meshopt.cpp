// EXT_meshopt_compression / KHR_meshopt_compression through meshoptimizer's decoders,
// following the extension's README (KhronosGroup/glTF, extensions/2.0/Vendor/
// EXT_meshopt_compression): modes ATTRIBUTES, TRIANGLES, INDICES; filters OCTAHEDRAL,
// QUATERNION, EXPONENTIAL applied after the codec, in place.
#include "io/gltf/compression/gltf_meshopt.h"

#include <meshoptimizer.h>

#include <algorithm>

#include "core/error.h"

namespace penumbra {

namespace {

// Densest output the codecs produce: the vertex codec spends at least 2 header bits per
// 16 bytes (64:1), the index codecs at least a byte per triangle or per index. A view
// claiming more than 4x that is corrupt, and is refused before anything is allocated.
constexpr uint64_t kMaxRatio = 256;
constexpr uint64_t kSlack = 4096;

struct MeshoptView {
    int buffer = -1;
    uint64_t offset = 0, length = 0, stride = 0, count = 0;
    std::string mode, filter = "NONE";
};

uint64_t number(const tinygltf::Value& v, const char* key, bool required, bool& ok) {
    if (!v.Has(key)) {
        if (required) ok = false;
        return 0;
    }
    const tinygltf::Value& n = v.Get(key);
    if (!n.IsNumber() || n.GetNumberAsDouble() < 0 || n.GetNumberAsDouble() > 9.0e15) {
        ok = false;
        return 0;
    }
    return uint64_t(n.GetNumberAsDouble());
}

[[noreturn]] void fail(const std::string& where, const std::string& problem) {
    throw SceneError(where + ": " + problem);
}

// Buffers that stand in for a fallback: their bytes are not in the file.
struct Fallbacks {
    std::vector<bool> is_fallback;
    std::vector<uint64_t> length;  // the byteLength the file declares
};

MeshoptView read_extension(const tinygltf::Value& e, const std::string& where) {
    bool ok = e.IsObject();
    MeshoptView m;
    m.buffer = int(number(e, "buffer", true, ok));
    m.offset = number(e, "byteOffset", false, ok);
    m.length = number(e, "byteLength", true, ok);
    m.stride = number(e, "byteStride", true, ok);
    m.count = number(e, "count", true, ok);
    if (!ok || !e.Has("mode") || !e.Get("mode").IsString())
        fail(where,
             "buffer, byteLength, byteStride, count and mode must be given, as non-negative "
             "numbers and a string");
    m.mode = e.Get("mode").Get<std::string>();
    if (e.Has("filter")) {
        if (!e.Get("filter").IsString()) fail(where, "filter must be a string");
        m.filter = e.Get("filter").Get<std::string>();
    }
    return m;
}

// Source: the compressed bytes.
const std::vector<unsigned char>& source(const tinygltf::Model& model, const MeshoptView& m,
                                         const std::string& where) {
    if (size_t(m.buffer) >= model.buffers.size())
        fail(where, "buffer index " + std::to_string(m.buffer) + " out of range (" +
                        std::to_string(model.buffers.size()) + " buffers)");
    const std::vector<unsigned char>& src = model.buffers[size_t(m.buffer)].data;
    if (m.offset > src.size() || m.length > src.size() - m.offset)
        fail(where, "compressed bytes [" + std::to_string(m.offset) + ", +" +
                        std::to_string(m.length) + ") outside buffer " + std::to_string(m.buffer) +
                        " (" + std::to_string(src.size()) + " bytes)");
    return src;
}

// Destination: this view's range of its own buffer, grown when that is a fallback buffer.
unsigned char* destination(tinygltf::Model& model, const tinygltf::BufferView& view,
                           const MeshoptView& m, const Fallbacks& fallbacks,
                           const std::string& where) {
    const bool attributes = m.mode == "ATTRIBUTES";
    if (!attributes && m.mode != "TRIANGLES" && m.mode != "INDICES")
        fail(where, "unknown mode '" + m.mode + "'");
    if (attributes ? (m.stride == 0 || m.stride > 256 || m.stride % 4 != 0)
                   : (m.stride != 2 && m.stride != 4))
        fail(where, "byteStride " + std::to_string(m.stride) + " is not allowed in mode " + m.mode);
    if (m.mode == "TRIANGLES" && m.count % 3 != 0)
        fail(where,
             "count " + std::to_string(m.count) + " is not a multiple of 3 in mode TRIANGLES");
    const uint64_t size = m.count * m.stride;  // < 2^64: count < 9e15, stride <= 256
    if (m.count > (uint64_t(1) << 40) || size > kMaxRatio * m.length + kSlack)
        fail(where, std::to_string(m.count) + " elements of " + std::to_string(m.stride) +
                        " bytes cannot come from " + std::to_string(m.length) +
                        " compressed bytes");
    if (size > view.byteLength)
        fail(where, "count * byteStride = " + std::to_string(size) +
                        " exceeds the bufferView's "
                        "byteLength " +
                        std::to_string(view.byteLength));
    if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size())
        fail(where, "bufferView buffer index " + std::to_string(view.buffer) + " out of range");
    if (size_t(view.buffer) == size_t(m.buffer))
        fail(where, "decodes into the buffer holding its compressed bytes");
    std::vector<unsigned char>& dst = model.buffers[size_t(view.buffer)].data;
    const uint64_t end = uint64_t(view.byteOffset) + size;
    if (fallbacks.is_fallback[size_t(view.buffer)]) {
        // The fallback buffer has no bytes in the file; it grows to what its views
        // decode, never to a byteLength the file merely declares.
        if (end > fallbacks.length[size_t(view.buffer)])
            fail(where, "decoded range ends at byte " + std::to_string(end) +
                            ", past the fallback "
                            "buffer's byteLength " +
                            std::to_string(fallbacks.length[size_t(view.buffer)]));
        if (dst.size() < end) dst.resize(size_t(end), 0);
    } else if (end > dst.size()) {
        fail(where, "decoded range ends at byte " + std::to_string(end) + ", past buffer " +
                        std::to_string(view.buffer) + " (" + std::to_string(dst.size()) +
                        " bytes)");
    }
    return dst.data() + view.byteOffset;
}

void decode(unsigned char* out, const unsigned char* in, const MeshoptView& m,
            const std::string& where) {
    int rc = 0;
    if (m.mode == "ATTRIBUTES")
        rc = meshopt_decodeVertexBuffer(out, size_t(m.count), size_t(m.stride), in,
                                        size_t(m.length));
    else if (m.mode == "TRIANGLES")
        rc =
            meshopt_decodeIndexBuffer(out, size_t(m.count), size_t(m.stride), in, size_t(m.length));
    else
        rc = meshopt_decodeIndexSequence(out, size_t(m.count), size_t(m.stride), in,
                                         size_t(m.length));
    if (rc != 0) fail(where, "cannot decode (meshoptimizer error " + std::to_string(rc) + ")");
}

// The filters run on the decoded values, in place.
void apply_filter(unsigned char* out, const MeshoptView& m, const std::string& where) {
    if (m.filter == "NONE") return;
    if (m.mode != "ATTRIBUTES") fail(where, "filter " + m.filter + " needs mode ATTRIBUTES");
    if (m.filter == "OCTAHEDRAL") {
        if (m.stride != 4 && m.stride != 8) fail(where, "OCTAHEDRAL needs byteStride 4 or 8");
        meshopt_decodeFilterOct(out, size_t(m.count), size_t(m.stride));
    } else if (m.filter == "QUATERNION") {
        if (m.stride != 8) fail(where, "QUATERNION needs byteStride 8");
        meshopt_decodeFilterQuat(out, size_t(m.count), size_t(m.stride));
    } else if (m.filter == "EXPONENTIAL") {
        meshopt_decodeFilterExp(out, size_t(m.count), size_t(m.stride));
    } else {
        fail(where, "unsupported filter '" + m.filter + "'");
    }
}

}  // namespace

void decode_meshopt(tinygltf::Model& model,
                    const std::vector<std::pair<int, uint64_t>>& fallback_buffers,
                    const std::string& file) {
    Fallbacks fallbacks{std::vector<bool>(model.buffers.size(), false),
                        std::vector<uint64_t>(model.buffers.size(), 0)};
    for (const auto& [index, length] : fallback_buffers)
        if (size_t(index) < model.buffers.size()) {
            fallbacks.is_fallback[size_t(index)] = true;
            fallbacks.length[size_t(index)] = length;
        }

    for (size_t v = 0; v < model.bufferViews.size(); ++v) {
        const tinygltf::BufferView& view = model.bufferViews[v];
        const char* ext_name = nullptr;
        for (const char* name : {"EXT_meshopt_compression", "KHR_meshopt_compression"})
            if (view.extensions.count(name)) ext_name = name;
        if (!ext_name) continue;
        const std::string where = file + ": bufferViews[" + std::to_string(v) + "]: " + ext_name;
        const MeshoptView m = read_extension(view.extensions.at(ext_name), where);
        const std::vector<unsigned char>& src = source(model, m, where);
        unsigned char* out = destination(model, view, m, fallbacks, where);
        decode(out, src.data() + m.offset, m, where);
        apply_filter(out, m, where);
    }
}

}  // namespace penumbra
