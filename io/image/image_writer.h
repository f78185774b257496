// Writing renders: OpenEXR (one multi-channel file: the beauty and named AOV layers,
// with typed header attributes) and 8-bit previews (PNG/JPEG) through an OCIO
// display/view. Every write goes to a temporary file in the target folder that is renamed
// over the destination only when complete, so a failed or interrupted write never leaves
// a half-written file over a good one.
#pragma once

#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "core/image.h"
#include "core/math/transform.h"
#include "io/color/color.h"

namespace penumbra {

// EXR header values. A Mat4 is given in penumbra's convention (column vectors, p' = M p)
// and stored transposed, as OpenEXR's Imath matrices multiply row vectors (p' = p M).
using MetadataValue = std::variant<std::string, int, float, double, Mat4, Chromaticities>;
using Metadata = std::vector<std::pair<std::string, MetadataValue>>;

// A group of channels of one EXR. The beauty has an empty name and channels R, G, B, A;
// a layer's channels are written "<name>.<channel>" (e.g. "Normal.X"), which OIIO, Nuke
// and Blender's compositor read as layer (pass) and channel.
struct ExrLayer {
    std::string name;
    std::vector<std::string> channels;  // one per image channel
    const Image* image = nullptr;       // the file's size; not owned
    bool full_float = false;  // kept 32-bit under ExrOptions::half (depth, positions, counts)
};

struct ExrOptions {
    bool half = false;  // 16-bit float for colour layers
    std::string compression = "zip";
};

// The compressions write_exr accepts (OpenEXR's): none, rle, zips, zip, piz, pxr24, b44,
// b44a, dwaa, dwab. pxr24, b44(a) and dwa(a|b) are lossy.
const std::vector<std::string>& exr_compressions();

// Throws SceneError (naming the path) when the file cannot be written, and for an
// unknown compression or layers of different sizes.
void write_exr(const std::string& path, const std::vector<ExrLayer>& layers,
               const Metadata& metadata, const ExrOptions& options = {});
// The beauty alone (RGB or RGBA), 32-bit float, zip.
void write_exr(const std::string& path, const Image& image, const Metadata& metadata = {});

// A linear image (in color's working space) through color's display/view/look, exposure
// in stops applied first, quantised to 8 bits; the format follows the extension (.png,
// .jpg, .jpeg). Without a pipeline: the built-in config's sRGB Standard view, i.e. the
// sRGB curve on values clamped to [0,1]. An RGBA image with alpha below 1 somewhere (a
// transparent background) gives an RGBA PNG with straight colour, as PNG stores it;
// otherwise (and as JPEG) the preview is RGB.
void write_preview(const std::string& path, const Image& image, const ColorPipeline& color,
                   float exposure = 0);
void write_preview(const std::string& path, const Image& image, float exposure = 0);
// The preview path for an output: "out/x.exr" -> "out/x.png".
std::string preview_path_for(const std::string& output_path);

}  // namespace penumbra
