// tinygltf parsing: images captured undecoded, compressed geometry decoded
// (gltf_compression.h), tinygltf's messages logged on one line.
#include "io/gltf/gltf_parse.h"

#include <algorithm>
#include <cstring>
#include <iterator>
#include <exception>
#include <filesystem>
#include <fstream>
#include <optional>

#include "core/error.h"
#include "core/log.h"
#include "io/gltf/compression/gltf_compression.h"
#include "io/gltf/animation/gltf_pointer_channels.h"
#include "io/gltf/gltf_signature.h"

namespace penumbra {

namespace {

// Extensions whose meaning we implement.
const char* const kSupportedExtensions[] = {
    "KHR_animation_pointer",
    "KHR_draco_mesh_compression",
    "KHR_lights_punctual",
    "KHR_materials_anisotropy",
    "KHR_materials_clearcoat",
    "KHR_materials_diffuse_transmission",
    "KHR_materials_dispersion",
    "KHR_materials_emissive_strength",
    "KHR_materials_ior",
    "KHR_materials_iridescence",
    "KHR_materials_pbrSpecularGlossiness",
    "KHR_materials_sheen",
    "KHR_materials_specular",
    "KHR_materials_transmission",
    "KHR_materials_unlit",
    "KHR_materials_variants",
    "KHR_materials_volume",
    "KHR_mesh_quantization",
    "KHR_node_visibility",
    "KHR_meshopt_compression",
    "KHR_texture_basisu",
    "KHR_texture_transform",
    "EXT_cameras_sensor",
    "EXT_mesh_gpu_instancing",
    "EXT_meshopt_compression",
    "EXT_texture_webp"};

}  // namespace

bool is_supported_extension(const std::string& name) {
    for (const char* s : kSupportedExtensions)
        if (name == s) return true;
    return false;
}

namespace {

// tinygltf's image callback. It keeps the encoded bytes of images given by a URI (data
// or file) so that OIIO decodes every image in one place (io/image/image_reader.cpp). Images
// in a bufferView are copied later, once their byte range has been checked: tinygltf
// hands them over without checking that the view lies inside its buffer.
bool capture_image(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                   const unsigned char* bytes, int size, void*) {
    if (image->bufferView >= 0) return true;
    image->image.assign(bytes, bytes + size);
    image->as_is = true;
    return true;
}

// tinygltf's messages on one line: newlines become "; " and data: URIs, which it
// quotes whole, are shortened.
std::string one_line(const std::string& text) {
    std::string out;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\n' || c == '\r') {
            while (!out.empty() && out.back() == ' ') out.pop_back();
            if (out.size() >= 2 && out.compare(out.size() - 2, 2, "; ") != 0) out += "; ";
            continue;
        }
        out += c;
        if (c == ',' && out.size() >= 7 && out.compare(out.size() - 7, 7, "base64,") == 0) {
            size_t end = i + 1;
            while (end < text.size() && (std::isalnum(static_cast<unsigned char>(text[end])) ||
                                         text[end] == '+' || text[end] == '/' || text[end] == '='))
                ++end;
            if (end - (i + 1) > 24) {
                out += text.substr(i + 1, 16) + "...";
                i = end - 1;
            }
        }
    }
    while (!out.empty() && (out.back() == ' ' || out.back() == ';')) out.pop_back();
    return out;
}

// tinygltf's warnings, one line per kind: repeats (one per element) are counted, not
// printed again. It wrongly requires skins[].inverseBindMatrices, which is optional
// (identity; glTF 2.0, section 5.28), so that line is dropped.
void log_lines(const std::string& file, const std::string& text, bool strict) {
    std::vector<std::pair<std::string, int>> lines;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        const std::string line = one_line(text.substr(start, end - start));
        start = end + 1;
        if (line.empty() || line == "'inverseBindMatrices' property is missing in Skin.") continue;
        auto it = std::find_if(lines.begin(), lines.end(), [&](auto& l) { return l.first == line; });
        if (it == lines.end())
            lines.emplace_back(line, 1);
        else
            ++it->second;
    }
    for (const auto& [line, n] : lines) {
        const std::string msg =
            file + ": " + line + (n > 1 ? " (" + std::to_string(n) + " times)" : "");
        if (strict) throw SceneError(msg + " [--strict]");
        LOG_WARNING(msg);
    }
}

// tinygltf takes a data: URI of a MIME type it does not know (image/ktx2, image/webp) for
// a file name and warns that the file is missing; the texture table decodes such URIs
// itself (io/image/data_uri.h), so those warnings are dropped.
void drop_data_uri_warnings(const tinygltf::Model& model, std::string& warn) {
    std::vector<std::string> drop;
    for (size_t i = 0; i < model.images.size(); ++i)
        if (model.images[i].image.empty() && model.images[i].uri.compare(0, 5, "data:") == 0)
            drop.push_back("Failed to load external 'uri' for image[" + std::to_string(i) +
                           "] name = [" + model.images[i].name + "]");
    if (drop.empty()) return;
    std::string kept;
    size_t start = 0;
    while (start < warn.size()) {
        size_t end = warn.find('\n', start);
        if (end == std::string::npos) end = warn.size();
        const std::string line = warn.substr(start, end - start);
        start = end + 1;
        if (line.compare(0, 22, "File not found : data:") == 0 ||
            std::find(drop.begin(), drop.end(), line) != drop.end())
            continue;
        kept += line + "\n";
    }
    warn = kept;
}

}  // namespace

tinygltf::Model parse_gltf(const std::string& path, bool strict) {
    std::error_code ec;
    char magic[4] = {};
    std::ifstream file(path, std::ios::binary);
    if (!std::filesystem::is_regular_file(path, ec) || !file)
        throw SceneError(path + ": cannot open file");
    check_gltf_signature(path);
    file.read(magic, sizeof(magic));
    // GLB is recognised by its header, not its extension (glTF 2.0, section 4.4.2).
    const bool binary = file.gcount() == 4 && std::memcmp(magic, "glTF", 4) == 0;

    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(capture_image, nullptr);
    tinygltf::Model model;
    std::string err, warn;
    bool ok = false;
    const std::optional<CompressedGltf> compressed = prepare_compressed_gltf(path, binary);
    try {
        if (compressed) {
            // tinygltf's base directory for external buffers and images, as
            // Load*FromFile would compute it.
            const std::string dir = std::filesystem::path(path).parent_path().string();
            const std::string& bytes = compressed->bytes;
            ok = binary ? loader.LoadBinaryFromMemory(
                              &model, &err, &warn,
                              reinterpret_cast<const unsigned char*>(bytes.data()),
                              unsigned(bytes.size()), dir)
                        : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(),
                                                     unsigned(bytes.size()), dir);
        } else {
            ok = binary ? loader.LoadBinaryFromFile(&model, &err, &warn, path)
                        : loader.LoadASCIIFromFile(&model, &err, &warn, path);
        }
    } catch (const std::exception& e) {
        // tinygltf throws on some malformed input (e.g. an empty data: URI).
        throw SceneError(path + ": " + one_line(e.what()));
    }
    if (ok && std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(),
                        "KHR_animation_pointer") != model.extensionsUsed.end()) {
        std::string bytes;
        if (compressed) {
            bytes = compressed->bytes;
        } else {
            std::ifstream in(path, std::ios::binary);
            bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        }
        restore_pointer_channels(model, bytes, binary, path, warn, err);
    }
    drop_data_uri_warnings(model, warn);
    log_lines(path, warn, strict);
    // tinygltf reads extensionsRequired before buffers and accessors, which an unknown
    // extension may leave without data; name the extension, not the accessor it broke.
    if (!ok)
        for (const std::string& name : model.extensionsRequired)
            if (!is_supported_extension(name))
                throw SceneError(path + ": extensionsRequired: unsupported extension '" + name +
                                 "'");
    if (!ok) throw SceneError(path + ": " + (err.empty() ? "cannot parse glTF" : one_line(err)));
    log_lines(path, err, strict);  // tinygltf reports some recoverable problems as errors
    if (compressed) decode_compressed_gltf(model, compressed->fixups, path);
    return model;
}

}  // namespace penumbra
