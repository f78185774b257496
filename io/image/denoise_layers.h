// The denoiser's input (core/denoise/denoise_input.h) as EXR layers, for the farm: a row
// band of a render that denoises writes them beside its beauty, full float so the values
// come back exactly, and the merge rebuilds the whole image's input from the assembled
// bands, so its denoiser reads the numbers one machine's reads. No final image holds them.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/denoise/denoise_input.h"
#include "io/image/image_writer.h"

namespace penumbra {

// Every channel of these layers is named "DenoiseInput.<layer>.<channel>".
inline constexpr char kDenoiseInputLayer[] = "DenoiseInput";

// The layers, pointing into input: ColorA, ColorB and ColorVariance (R, G, B), GuideA,
// GuideB and GuideVariance (AlbedoR, AlbedoG, AlbedoB, NormalX, NormalY, NormalZ, Depth,
// Visibility: denoise_input.h's guide channels in its order). All full float.
std::vector<ExrLayer> denoise_input_layers(const DenoiseInput& input);

// The input from an image with those layers: read(names) returns the channels of those
// full names, in that order, as one image (and throws when one is missing).
using ChannelReader = std::function<Image(const std::vector<std::string>& names)>;
DenoiseInput read_denoise_input(const ChannelReader& read);

}  // namespace penumbra
