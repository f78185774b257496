// Images as the denoiser works on them: one contiguous plane per channel, so that the
// loops over a row of one channel vectorise.
#pragma once

#include <cstddef>
#include <vector>

#include "core/image.h"

namespace penumbra {

struct Planes {
    int width = 0, height = 0, channels = 0;
    std::vector<float> data;  // channel c, pixel (x, y) at (c * height + y) * width + x

    Planes() = default;
    Planes(int w, int h, int c, float value = 0)
        : width(w), height(h), channels(c), data(size_t(w) * h * c, value) {}
    size_t pixels() const { return size_t(width) * height; }
    float* plane(int c) { return data.data() + size_t(c) * pixels(); }
    const float* plane(int c) const { return data.data() + size_t(c) * pixels(); }
    float& at(int c, int x, int y) { return plane(c)[size_t(y) * width + x]; }
    float at(int c, int x, int y) const { return plane(c)[size_t(y) * width + x]; }
};

// Channels [first, first + count) of an interleaved image.
Planes to_planes(const Image& image, int first, int count);
Planes to_planes(const Image& image);
Image to_image(const Planes& planes);
// Channels [first, first + count) of p.
Planes channels(const Planes& p, int first, int count);

}  // namespace penumbra
