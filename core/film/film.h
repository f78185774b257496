// The image being rendered: per pixel, the weighted sum of radiance samples and of their
// filter weights. Each pixel is written by one thread at a time (its tile's), in sample
// order, so the result does not depend on the thread count.
#pragma once

#include <cstdint>
#include <vector>

#include "core/image.h"
#include "core/math/vec.h"

namespace penumbra {

class Film {
public:
    Film(int width, int height);
    int width() const { return m_width; }
    int height() const { return m_height; }
    // Adds a sample with filter weight w. Non-finite radiance is counted, not added.
    void add_sample(int x, int y, Spectrum L, float w);
    // Linear RGBA image, alpha = 1.
    Image resolve() const;
    uint64_t nonfinite_samples() const;

private:
    struct Pixel {
        double sum[3] = {0, 0, 0};
        double weight = 0;
        uint32_t nonfinite = 0;
    };
    int m_width, m_height;
    std::vector<Pixel> m_pixels;
};

}  // namespace penumbra
