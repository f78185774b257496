// Compressed geometry around tinygltf. Debian 12's tinygltf has no Draco and checks, while
// parsing, that every primitive's accessors have a bufferView and that a GLB buffer
// without a uri fits the BIN chunk, so it rejects Draco primitives (accessors without a
// bufferView) and meshopt fallback buffers (a byteLength but no bytes). We relax exactly
// those two things in the JSON, let tinygltf parse, undo them, then decode.
#include "io/gltf/compression/gltf_compression.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "io/gltf/compression/gltf_draco.h"
#include "io/gltf/compression/gltf_meshopt.h"

namespace penumbra {

namespace {

using nlohmann::json;

const char* const kMeshopt[] = {"EXT_meshopt_compression", "KHR_meshopt_compression"};
const char* const kDraco = "KHR_draco_mesh_compression";

uint32_t read_u32(const std::string& s, size_t at) {
    uint32_t v = 0;
    std::memcpy(&v, s.data() + at, 4);  // GLB is little-endian, as is every target we build
    return v;
}

void append_u32(std::string& s, uint32_t v) {
    char b[4];
    std::memcpy(b, &v, 4);
    s.append(b, 4);
}

bool is_fallback_buffer(const json& buffer) {
    const auto ext = buffer.find("extensions");
    if (ext == buffer.end() || !ext->is_object()) return false;
    for (const char* name : kMeshopt) {
        const auto e = ext->find(name);
        if (e != ext->end() && e->is_object() && e->value("fallback", false) == true) return true;
    }
    return false;
}

// The relaxations of the file comment, applied to the parsed JSON in place.
CompressedFixups relax(json& gltf) {
    CompressedFixups fixups;
    if (gltf.contains("buffers") && gltf["buffers"].is_array()) {
        json& buffers = gltf["buffers"];
        for (size_t i = 0; i < buffers.size(); ++i) {
            json& b = buffers[i];
            if (!b.is_object() || !is_fallback_buffer(b) || b.contains("uri")) continue;
            const auto length = b.find("byteLength");
            if (length == b.end() || !length->is_number_unsigned()) continue;  // tinygltf says
            fixups.fallback_buffers.emplace_back(int(i), length->get<uint64_t>());
            b["uri"] = "data:application/octet-stream;base64,AAAA";
            b["byteLength"] = 3;
        }
    }
    if (!gltf.contains("meshes") || !gltf["meshes"].is_array() || !gltf.contains("accessors") ||
        !gltf["accessors"].is_array())
        return fixups;
    json& accessors = gltf["accessors"];
    auto point_at_placeholder = [&](const json& index) {
        if (!index.is_number_unsigned() || index.get<uint64_t>() >= accessors.size()) return;
        json& a = accessors[index.get<size_t>()];
        if (!a.is_object() || a.contains("bufferView")) return;
        if (fixups.placeholder_view < 0) {
            if (!gltf.contains("bufferViews")) gltf["bufferViews"] = json::array();
            fixups.placeholder_view = int(gltf["bufferViews"].size());
            gltf["bufferViews"].push_back({{"buffer", 0}, {"byteLength", 1}});
        }
        a["bufferView"] = fixups.placeholder_view;
        fixups.placeholder_accessors.push_back(index.get<int>());
    };
    for (const json& mesh : gltf["meshes"]) {
        if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array())
            continue;
        for (const json& prim : mesh["primitives"]) {
            if (!prim.is_object() || !prim.contains("extensions") ||
                !prim["extensions"].is_object() || !prim["extensions"].contains(kDraco))
                continue;
            if (prim.contains("indices")) point_at_placeholder(prim["indices"]);
            if (prim.contains("attributes") && prim["attributes"].is_object())
                for (const json& index : prim["attributes"]) point_at_placeholder(index);
        }
    }
    return fixups;
}

bool uses_compression(const json& gltf) {
    const auto used = gltf.find("extensionsUsed");
    if (used == gltf.end() || !used->is_array()) return false;
    for (const json& name : *used) {
        if (!name.is_string()) continue;
        const std::string n = name.get<std::string>();
        if (n == kDraco || n == kMeshopt[0] || n == kMeshopt[1]) return true;
    }
    return false;
}

}  // namespace

std::optional<CompressedGltf> prepare_compressed_gltf(const std::string& path, bool binary) {
    std::ifstream in(path, std::ios::binary);
    std::error_code ec;
    const uint64_t file_size = std::filesystem::file_size(path, ec);
    if (ec) return std::nullopt;
    auto read = [&](size_t n) {
        std::string s(std::min<uint64_t>(n, file_size), '\0');  // a header may claim 4 GB
        in.read(s.data(), std::streamsize(n));
        s.resize(size_t(in.gcount()));
        return s;
    };
    // Only the JSON is read before deciding: for GLB (glTF 2.0, section 4.4) the 12-byte
    // header and the JSON chunk's; images and buffers only for files we rewrite.
    std::string head, text;
    if (binary) {
        head = read(20);
        if (head.size() < 20 || read_u32(head, 4) != 2 || read_u32(head, 16) != 0x4E4F534A)
            return std::nullopt;
        text = read(read_u32(head, 12));
        if (text.size() != read_u32(head, 12)) return std::nullopt;
    } else {
        text = read(file_size);  // one allocation, not one per doubling
    }
    if (text.find("_compression") == std::string::npos) return std::nullopt;  // most files
    json gltf = json::parse(text, nullptr, false);
    if (gltf.is_discarded() || !gltf.is_object() || !uses_compression(gltf)) return std::nullopt;

    CompressedGltf out;
    out.fixups = relax(gltf);
    text = gltf.dump();
    if (!binary) {
        out.bytes = std::move(text);
        return out;
    }
    while (text.size() % 4 != 0) text += ' ';  // JSON chunks pad with spaces (4.4.3.1)
    const std::string rest = read(file_size);  // BIN and later chunks
    // Only well-framed files are rewritten (a consistent header length, a BIN chunk inside
    // the file): with a recomputed header tinygltf would trust a BIN length past the end.
    if (read_u32(head, 8) != file_size ||
        (rest.size() >= 8 && read_u32(rest, 0) > rest.size() - 8) ||
        (!rest.empty() && rest.size() < 8))
        return std::nullopt;
    out.bytes = head.substr(0, 8);
    append_u32(out.bytes, uint32_t(12 + 8 + text.size() + rest.size()));
    append_u32(out.bytes, uint32_t(text.size()));
    append_u32(out.bytes, 0x4E4F534A);
    out.bytes += text;
    out.bytes += rest;
    return out;
}

void decode_compressed_gltf(tinygltf::Model& model, const CompressedFixups& fixups,
                            const std::string& file) {
    for (const auto& [index, length] : fixups.fallback_buffers)
        if (size_t(index) < model.buffers.size()) model.buffers[size_t(index)].data.clear();
    if (fixups.placeholder_view >= 0) {
        for (int a : fixups.placeholder_accessors)
            if (size_t(a) < model.accessors.size() &&
                model.accessors[size_t(a)].bufferView == fixups.placeholder_view)
                model.accessors[size_t(a)].bufferView = -1;
        if (model.bufferViews.size() == size_t(fixups.placeholder_view) + 1)
            model.bufferViews.pop_back();
    }
    decode_meshopt(model, fixups.fallback_buffers, file);
    decode_draco(model, file);
}

}  // namespace penumbra
