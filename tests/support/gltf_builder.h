// Writing small glTF files in tests: typed data packed into one buffer with a bufferView
// and accessor per array, emitted as .gltf with a data: URI, .gltf with an external
// .bin, or .glb; and a scratch folder per test to put them in.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace penumbra::test {

inline std::string base64(const std::vector<uint8_t>& in) {
    static const char* abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < in.size(); i += 3) {
        const uint32_t n = uint32_t(in[i]) << 16 | (i + 1 < in.size() ? in[i + 1] << 8 : 0) |
                           (i + 2 < in.size() ? in[i + 2] : 0);
        out += abc[n >> 18 & 63];
        out += abc[n >> 12 & 63];
        out += i + 1 < in.size() ? abc[n >> 6 & 63] : '=';
        out += i + 2 < in.size() ? abc[n & 63] : '=';
    }
    return out;
}

// A folder under the system temp dir named after the running test, removed at the end.
class ScratchDir {
public:
    ScratchDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        m_path = std::filesystem::temp_directory_path() /
                 ("penumbra_" + std::string(info->test_suite_name()) + "_" + info->name());
        std::filesystem::remove_all(m_path);
        std::filesystem::create_directories(m_path);
    }
    ~ScratchDir() { std::filesystem::remove_all(m_path); }
    std::string file(const std::string& name) const { return (m_path / name).string(); }
    std::string write(const std::string& name, const std::string& text) const {
        std::ofstream(file(name), std::ios::binary) << text;
        return file(name);
    }

private:
    std::filesystem::path m_path;
};

enum class BufferStorage { DataUri, ExternalBin, Glb };

constexpr int kByte = 5120, kUByte = 5121, kShort = 5122, kUShort = 5123, kUInt = 5125,
              kFloat = 5126;

class GltfBuilder {
public:
    // Appends `values` as a new bufferView and accessor; returns the accessor index.
    // `extra` is spliced into the accessor's JSON (e.g. "\"normalized\":true"). Float VEC3
    // accessors get the min and max glTF requires of POSITION unless `extra` gives its
    // own or is sparse (whose values the dense data do not show).
    template <typename T>
    int add(const std::vector<T>& values, int component_type, const std::string& type,
            std::string extra = "") {
        if constexpr (std::is_same_v<T, float>)
            if (type == "VEC3" && !values.empty() && extra.find("\"min\"") == std::string::npos &&
                extra.find("\"sparse\"") == std::string::npos)
                extra += (extra.empty() ? "" : ",") + vec3_bounds(values);
        while (m_buffer.size() % 4) m_buffer.push_back(0);
        const size_t offset = m_buffer.size(), bytes = values.size() * sizeof(T);
        m_buffer.resize(offset + bytes);
        if (bytes) std::memcpy(m_buffer.data() + offset, values.data(), bytes);
        const int d = type.back() - '0';
        const int n = type == "SCALAR" ? 1 : type.compare(0, 3, "MAT") == 0 ? d * d : d;
        add_view(offset, bytes);
        return add_accessor(int(m_views.size()) - 1, 0, component_type, type,
                            values.size() / size_t(n), extra);
    }
    void add_view(size_t offset, size_t length, int stride = 0) {
        std::string v = "{\"buffer\":0,\"byteOffset\":" + std::to_string(offset) +
                        ",\"byteLength\":" + std::to_string(length);
        if (stride) v += ",\"byteStride\":" + std::to_string(stride);
        m_views.push_back(v + "}");
    }
    int add_accessor(int view, size_t offset, int component_type, const std::string& type,
                     size_t count, const std::string& extra = "") {
        std::string a = "{";
        if (view >= 0)
            a += "\"bufferView\":" + std::to_string(view) +
                 ",\"byteOffset\":" + std::to_string(offset) + ",";
        a += "\"componentType\":" + std::to_string(component_type) +
             ",\"count\":" + std::to_string(count) + ",\"type\":\"" + type + "\"";
        if (!extra.empty()) a += "," + extra;
        m_accessors.push_back(a + "}");
        return int(m_accessors.size()) - 1;
    }
    std::vector<uint8_t>& bytes() { return m_buffer; }
    // A bufferView given as JSON (e.g. with extensions); returns its index.
    int add_view_json(const std::string& view) {
        m_views.push_back(view);
        return int(m_views.size()) - 1;
    }
    // Buffers after buffer 0 (which holds bytes()), as JSON; returns the new index.
    int add_buffer_json(const std::string& buffer) {
        m_more_buffers.push_back(buffer);
        return int(m_more_buffers.size());
    }

    // The whole file's JSON: `members` (meshes, nodes, ...) plus asset, buffers,
    // bufferViews and accessors. `bin_uri` names the external buffer file.
    std::string json(const std::string& members, BufferStorage storage,
                     const std::string& bin_uri = "data.bin") const {
        std::string buffer = "{\"byteLength\":" + std::to_string(m_buffer.size());
        if (storage == BufferStorage::DataUri)
            buffer += ",\"uri\":\"data:application/octet-stream;base64," + base64(m_buffer) + "\"";
        else if (storage == BufferStorage::ExternalBin)
            buffer += ",\"uri\":\"" + bin_uri + "\"";
        std::string j = "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[" + buffer + "}";
        for (const std::string& b : m_more_buffers) j += "," + b;
        j += "]";
        j += ",\"bufferViews\":[" + join(m_views) + "],\"accessors\":[" + join(m_accessors) + "]";
        if (!members.empty()) j += "," + members;
        return j + "}";
    }

    // Writes the scene to dir/name (.gltf or .glb as `storage` says); returns its path.
    std::string write(const ScratchDir& dir, const std::string& name, const std::string& members,
                      BufferStorage storage) const {
        const std::string j = json(members, storage);
        if (storage == BufferStorage::ExternalBin)
            std::ofstream(dir.file("data.bin"), std::ios::binary)
                .write(reinterpret_cast<const char*>(m_buffer.data()),
                       std::streamsize(m_buffer.size()));
        if (storage != BufferStorage::Glb) return dir.write(name, j);
        // GLB: 12-byte header, JSON chunk padded with spaces, BIN chunk padded with zeros.
        std::string js = j;
        while (js.size() % 4) js += ' ';
        std::vector<uint8_t> bin = m_buffer;
        while (bin.size() % 4) bin.push_back(0);
        std::vector<uint8_t> out;
        auto u32 = [&](uint32_t v) {
            for (int i = 0; i < 4; ++i) out.push_back(uint8_t(v >> (8 * i)));
        };
        out.insert(out.end(), {'g', 'l', 'T', 'F'});
        u32(2);
        u32(uint32_t(12 + 8 + js.size() + 8 + bin.size()));
        u32(uint32_t(js.size()));
        u32(0x4E4F534A);  // "JSON"
        out.insert(out.end(), js.begin(), js.end());
        u32(uint32_t(bin.size()));
        u32(0x004E4942);  // "BIN\0"
        out.insert(out.end(), bin.begin(), bin.end());
        std::ofstream(dir.file(name), std::ios::binary)
            .write(reinterpret_cast<const char*>(out.data()), std::streamsize(out.size()));
        return dir.file(name);
    }

private:
    static std::string vec3_bounds(const std::vector<float>& v) {
        float lo[3], hi[3];
        for (int c = 0; c < 3; ++c) lo[c] = hi[c] = v[size_t(c)];
        for (size_t i = 0; i + 2 < v.size(); i += 3)
            for (int c = 0; c < 3; ++c) {
                lo[c] = std::min(lo[c], v[i + size_t(c)]);
                hi[c] = std::max(hi[c], v[i + size_t(c)]);
            }
        // max_digits10, so that the bounds read back exactly.
        auto list = [](const float* x) {
            std::ostringstream s;
            s.precision(9);
            s << "[" << x[0] << "," << x[1] << "," << x[2] << "]";
            return s.str();
        };
        return "\"min\":" + list(lo) + ",\"max\":" + list(hi);
    }
    static std::string join(const std::vector<std::string>& v) {
        std::string s;
        for (size_t i = 0; i < v.size(); ++i) s += (i ? "," : "") + v[i];
        return s;
    }
    std::vector<uint8_t> m_buffer;
    std::vector<std::string> m_views, m_accessors, m_more_buffers;
};

// A one-node scene around mesh 0, for the common case.
inline std::string one_mesh_scene(const std::string& primitive) {
    return "\"meshes\":[{\"primitives\":[" + primitive +
           "]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],\"scene\":0";
}

}  // namespace penumbra::test
