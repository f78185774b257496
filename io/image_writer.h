// Writing renders: linear float OpenEXR with metadata, and 8-bit previews (PNG/JPEG)
// with the sRGB transfer. Every write goes to a temporary file in the target folder that
// is renamed over the destination only when complete, so a failed or interrupted write
// never leaves a half-written file over a good one.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/image.h"

namespace penumbra {

using Metadata = std::vector<std::pair<std::string, std::string>>;

// Throws SceneError (naming the path) when the file cannot be written.
void write_exr(const std::string& path, const Image& image, const Metadata& metadata = {});
// Clamps to [0,1] after the sRGB transfer (exposure in stops applied first); the format
// follows the extension (.png, .jpg, .jpeg).
void write_preview(const std::string& path, const Image& image, float exposure = 0);
// The preview path for an output: "out/x.exr" -> "out/x.png".
std::string preview_path_for(const std::string& output_path);

}  // namespace penumbra
