// Internal to io/: KHR_draco_mesh_compression, triangle primitives whose indices and
// attributes are one Draco mesh, decoded by libdraco into a new buffer.
#pragma once

#include <tiny_gltf.h>

#include <string>

namespace penumbra {

// Decodes each Draco primitive and points its indices and attribute accessors at the
// decoded data (in the accessors' own componentType), in a buffer appended to the model.
// Throws SceneError "<file>: meshes[i].primitives[j]: KHR_draco_mesh_compression: ...".
void decode_draco(tinygltf::Model& model, const std::string& file);

}  // namespace penumbra
