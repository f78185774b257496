// Reading a glTF or GLB file into tinygltf's model: the signature checked, images kept
// encoded (io/image/image_reader.cpp decodes them all), compressed geometry decoded.
#pragma once

#include <string>

#include "io/gltf/gltf_context.h"

namespace penumbra {

// Whether penumbra implements the extension's meaning (extensionsRequired may name it).
bool is_supported_extension(const std::string& name);

// Parses the file at path; tinygltf's warnings are logged (errors with `strict`). Throws
// SceneError naming the file, and the extension when an unsupported required one broke
// the parse.
tinygltf::Model parse_gltf(const std::string& path, bool strict);

}  // namespace penumbra
