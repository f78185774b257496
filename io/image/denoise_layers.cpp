#include "io/image/denoise_layers.h"

namespace penumbra {

namespace {

struct DenoiseLayout {
    const char* layer;
    Image DenoiseInput::*image;
    bool guide;  // kGuideChannels channels, else colour's three
};

const DenoiseLayout kLayouts[] = {
    {"ColorA", &DenoiseInput::color_a, false},
    {"ColorB", &DenoiseInput::color_b, false},
    {"ColorVariance", &DenoiseInput::color_variance, false},
    {"GuideA", &DenoiseInput::guide_a, true},
    {"GuideB", &DenoiseInput::guide_b, true},
    {"GuideVariance", &DenoiseInput::guide_variance, true},
};

const std::vector<std::string>& channels_of(const DenoiseLayout& l) {
    static_assert(kGuideChannels == 8 && kGuideAlbedo == 0 && kGuideNormal == 3 &&
                  kGuideDepth == 6 && kGuideVisibility == 7);
    static const std::vector<std::string> guide = {"AlbedoR", "AlbedoG", "AlbedoB", "NormalX",
                                                   "NormalY", "NormalZ", "Depth",   "Visibility"};
    static const std::vector<std::string> color = {"R", "G", "B"};
    return l.guide ? guide : color;
}

std::string layer_name(const DenoiseLayout& l) {
    return std::string(kDenoiseInputLayer) + "." + l.layer;
}

}  // namespace

std::vector<ExrLayer> denoise_input_layers(const DenoiseInput& input) {
    std::vector<ExrLayer> layers;
    for (const DenoiseLayout& l : kLayouts)
        layers.push_back({layer_name(l), channels_of(l), &(input.*l.image), true});
    return layers;
}

DenoiseInput read_denoise_input(const ChannelReader& read) {
    DenoiseInput input;
    for (const DenoiseLayout& l : kLayouts) {
        std::vector<std::string> names;
        for (const std::string& c : channels_of(l)) names.push_back(layer_name(l) + "." + c);
        input.*l.image = read(names);
    }
    return input;
}

}  // namespace penumbra
