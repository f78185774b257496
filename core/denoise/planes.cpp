#include "core/denoise/planes.h"

#include <algorithm>

namespace penumbra {

Planes to_planes(const Image& image, int first, int count) {
    Planes p(image.width, image.height, count);
    const size_t n = p.pixels();
    for (int c = 0; c < count; ++c) {
        float* out = p.plane(c);
        for (size_t i = 0; i < n; ++i) out[i] = image.pixels[i * image.channels + first + c];
    }
    return p;
}

Planes to_planes(const Image& image) { return to_planes(image, 0, image.channels); }

Image to_image(const Planes& p) {
    Image image(p.width, p.height, p.channels);
    const size_t n = p.pixels();
    for (int c = 0; c < p.channels; ++c) {
        const float* in = p.plane(c);
        for (size_t i = 0; i < n; ++i) image.pixels[i * p.channels + c] = in[i];
    }
    return image;
}

Planes channels(const Planes& p, int first, int count) {
    Planes out(p.width, p.height, count);
    std::copy(p.plane(first), p.plane(first) + p.pixels() * count, out.data.begin());
    return out;
}

}  // namespace penumbra
