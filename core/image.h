// A decoded image in memory: linear float pixels, row 0 at the top, channels
// interleaved. Decoding and encoding live in io/; this is only the container.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/math/vec.h"

namespace penumbra {

struct Image {
    int width = 0, height = 0, channels = 0;
    std::vector<float> pixels;  // width * height * channels
    std::string name;           // file name or glTF element, for messages

    Image() = default;
    Image(int w, int h, int c) : width(w), height(h), channels(c), pixels(size_t(w) * h * c) {}
    float* at(int x, int y) { return &pixels[(size_t(y) * width + x) * channels]; }
    const float* at(int x, int y) const { return &pixels[(size_t(y) * width + x) * channels]; }
    // Any channel count read as RGBA: gray fills RGB; missing alpha is 1.
    Vec4 rgba(int x, int y) const;
};

}  // namespace penumbra
