// Internal to io/: EXT_meshopt_compression and KHR_meshopt_compression, bufferViews whose
// bytes are meshoptimizer's vertex or index codec output, decoded in place.
#pragma once

#include <tiny_gltf.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace penumbra {

// Decodes every compressed bufferView into its own buffer's range; fallback buffers
// (`fallback_buffers`: index, declared byteLength; empty data) get their bytes here.
// Throws SceneError "<file>: bufferViews[i]: EXT_meshopt_compression: ..." on bad data.
void decode_meshopt(tinygltf::Model& model,
                    const std::vector<std::pair<int, uint64_t>>& fallback_buffers,
                    const std::string& file);

}  // namespace penumbra
