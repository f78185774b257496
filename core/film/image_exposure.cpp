#include "core/film/image_exposure.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace penumbra {

ImageExposure measure_exposure(const Image& image, float exposure) {
    ImageExposure e;
    const float scale = std::exp2(exposure);
    std::vector<float> Y;
    Y.reserve(size_t(image.width) * size_t(image.height));
    size_t lit = 0, clipped = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const Vec4 c = image.rgba(x, y);
            // A transparent background's empty pixels are no part of the picture.
            if (image.channels == 4 && !(c.w > 0)) continue;
            float v = scale * luminance(Spectrum(c.x, c.y, c.z));
            if (!std::isfinite(v)) v = 0;
            Y.push_back(v);
            lit += v >= kLitLuminance;
            clipped += v > kClipLuminance;
        }
    e.pixels = Y.size();
    if (e.pixels == 0) return e;
    e.lit_fraction = double(lit) / double(e.pixels);
    e.clipped_fraction = double(clipped) / double(e.pixels);
    auto rank = [&](double q) {
        const size_t k = std::min(e.pixels - 1, size_t(std::ceil(q * double(e.pixels))) - 1);
        std::nth_element(Y.begin(), Y.begin() + std::ptrdiff_t(k), Y.end());
        return Y[k];
    };
    e.median = rank(0.5);
    e.p99 = rank(0.99);
    return e;
}

}  // namespace penumbra
