// Internal to io/: tinygltf (2.8) drops every animation channel whose target has no
// `node`, which is every KHR_animation_pointer channel, and reports each as an error. For
// a file that uses the extension, the channels are read again from the file's JSON (the
// GLB's JSON chunk), and those reports are taken out of tinygltf's messages.
#pragma once

#include <tiny_gltf.h>

#include <string>

namespace penumbra {

// Replaces every animation's channels with the file's own, pointer channels included
// (target_path "pointer", target_node -1, the pointer in
// target_extensions.KHR_animation_pointer), and removes tinygltf's reports of their
// missing node from `warn` and `err`. `bytes` is the .gltf JSON or the whole GLB. Does
// nothing unless the file lists KHR_animation_pointer in extensionsUsed. Throws
// SceneError naming `path` when the JSON is not what tinygltf parsed.
void restore_pointer_channels(tinygltf::Model& model, const std::string& bytes, bool binary,
                              const std::string& path, std::string& warn, std::string& err);

}  // namespace penumbra
