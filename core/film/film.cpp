#include "core/film/film.h"

#include <cmath>

namespace penumbra {

Film::Film(int width, int height)
    : m_width(width), m_height(height), m_pixels(size_t(width) * height) {}

void Film::add_sample(int x, int y, Spectrum L, float w) {
    Pixel& px = m_pixels[size_t(y) * m_width + x];
    if (!is_finite(L)) {
        // A NaN or Inf would poison the pixel forever; drop it and keep count.
        ++px.nonfinite;
        return;
    }
    px.sum[0] += double(L.x) * w;
    px.sum[1] += double(L.y) * w;
    px.sum[2] += double(L.z) * w;
    px.weight += w;
}

Image Film::resolve() const {
    Image img(m_width, m_height, 4);
    for (int y = 0; y < m_height; ++y)
        for (int x = 0; x < m_width; ++x) {
            const Pixel& px = m_pixels[size_t(y) * m_width + x];
            float* out = img.at(x, y);
            const double inv = px.weight != 0 ? 1.0 / px.weight : 0.0;
            for (int c = 0; c < 3; ++c) out[c] = static_cast<float>(px.sum[c] * inv);
            out[3] = 1;
        }
    return img;
}

uint64_t Film::nonfinite_samples() const {
    uint64_t n = 0;
    for (const Pixel& px : m_pixels) n += px.nonfinite;
    return n;
}

}  // namespace penumbra
