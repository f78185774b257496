// glTF colours are linear Rec.709 (sRGB primaries, D65); a render in another working
// space (ACEScg) needs them converted once, at load, by the 3x3 matrix the colour
// pipeline derives (ColorPipeline::rec709_to_working).
#pragma once

#include "core/math/mat3.h"
#include "core/scene/scene.h"

namespace penumbra {

// Converts the colours of a loaded scene in place: material colour factors (base,
// emissive, specular, sheen, attenuation, diffuse transmission), the images of colour
// textures (the sRGB-encoded ones, RGB of 3 or 4 channels, alpha untouched: a matrix the
// lookup applies after filtering) and vertex colours. Data
// (metallic-roughness, normal, occlusion, transmission textures and factors) stays as it
// is. Lights are converted as the loader builds them (they hold their colour privately).
// Does nothing for the identity, so Rec.709 renders are unchanged bit for bit.
void convert_scene_colors(Scene& scene, const Mat3& rec709_to_working);
// The same for one image (an environment map): RGB of 3 or 4 channels; gray is left
// as it is (white maps to white).
void convert_image_colors(Image& image, const Mat3& rec709_to_working);

}  // namespace penumbra
