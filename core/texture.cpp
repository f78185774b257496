#include "core/texture.h"

#include <cmath>

namespace penumbra {

namespace {

int wrap(int i, int n, WrapMode mode) {
    switch (mode) {
        case WrapMode::ClampToEdge:
            return i < 0 ? 0 : (i >= n ? n - 1 : i);
        case WrapMode::MirroredRepeat: {
            const int period = 2 * n;
            int m = i % period;
            if (m < 0) m += period;
            return m < n ? m : period - 1 - m;
        }
        case WrapMode::Repeat:
        default: {
            int m = i % n;
            return m < 0 ? m + n : m;
        }
    }
}

}  // namespace

Vec4 lookup(const Texture& tex, const Image& img, Vec2 uv) {
    if (img.width == 0 || img.height == 0) return {1, 1, 1, 1};
    // Texel centers sit at half-integer coordinates.
    const float x = uv.x * img.width - 0.5f, y = uv.y * img.height - 0.5f;
    if (!std::isfinite(x) || !std::isfinite(y)) return img.rgba(0, 0);
    if (tex.nearest) {
        const int ix = wrap(static_cast<int>(std::floor(x + 0.5f)), img.width, tex.wrap_s);
        const int iy = wrap(static_cast<int>(std::floor(y + 0.5f)), img.height, tex.wrap_t);
        return img.rgba(ix, iy);
    }
    const float fx = std::floor(x), fy = std::floor(y);
    const float ax = x - fx, ay = y - fy;
    const int x0 = wrap(static_cast<int>(fx), img.width, tex.wrap_s);
    const int x1 = wrap(static_cast<int>(fx) + 1, img.width, tex.wrap_s);
    const int y0 = wrap(static_cast<int>(fy), img.height, tex.wrap_t);
    const int y1 = wrap(static_cast<int>(fy) + 1, img.height, tex.wrap_t);
    return img.rgba(x0, y0) * ((1 - ax) * (1 - ay)) + img.rgba(x1, y0) * (ax * (1 - ay)) +
           img.rgba(x0, y1) * ((1 - ax) * ay) + img.rgba(x1, y1) * (ax * ay);
}

}  // namespace penumbra
