// Is this file glTF at all? A .glb starts with the "glTF" magic and a .gltf is a JSON
// object; anything else (an HTML page saved as .glb, an image) is named as such before
// tinygltf's JSON parser reports a confusing syntax error.
#pragma once

#include <string>

namespace penumbra {

// Throws SceneError "<path>: not a glTF file: begins with '<!DOCTYPE'" (or "...: it is
// empty") unless the file starts with the GLB magic or, after an optional UTF-8 byte
// order mark and JSON whitespace, '{'. Needs a readable file.
void check_gltf_signature(const std::string& path);

}  // namespace penumbra
