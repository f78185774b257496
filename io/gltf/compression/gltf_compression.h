// Internal to io/: compressed geometry (KHR_draco_mesh_compression, EXT_ and
// KHR_meshopt_compression) around tinygltf, which Debian builds without Draco and which
// rejects the accessors and fallback buffers that have no data until they are decoded.
#pragma once

#include <tiny_gltf.h>

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace penumbra {

// What prepare_compressed_gltf changed in the JSON so that tinygltf accepts it, and
// decode_compressed_gltf undoes after parsing.
struct CompressedFixups {
    // Meshopt fallback buffers (no data in the file): index and declared byteLength. They
    // got a 3-byte data: URI for tinygltf.
    std::vector<std::pair<int, uint64_t>> fallback_buffers;
    // Accessors of Draco primitives without a bufferView were pointed at a placeholder
    // bufferView appended at index `placeholder_view`.
    int placeholder_view = -1;
    std::vector<int> placeholder_accessors;
};

// The file rewritten for tinygltf (GLB or glTF JSON, as the input was) and its fixups.
struct CompressedGltf {
    std::string bytes;
    CompressedFixups fixups;
};

// Reads `path`; when its extensionsUsed names a compression extension, returns its bytes
// with the JSON relaxed as CompressedFixups describes. Returns nothing for every other
// file, and for files whose JSON or GLB framing is broken: tinygltf then reads the file
// itself and reports the problem as it always did.
std::optional<CompressedGltf> prepare_compressed_gltf(const std::string& path, bool binary);

// After tinygltf parsed the output of prepare_compressed_gltf: undoes the fixups, then
// decodes meshopt bufferViews (gltf_meshopt.h) and Draco primitives (gltf_draco.h) so
// that the model's accessors read the decoded data. Throws SceneError naming `file`.
void decode_compressed_gltf(tinygltf::Model& model, const CompressedFixups& fixups,
                            const std::string& file);

}  // namespace penumbra
