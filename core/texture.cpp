#include "core/texture.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace penumbra {

namespace {

int wrap(int i, int n, WrapMode mode) {
    // Inside the image every mode is the identity: no integer division for the
    // common case (two to four per bilinear tap).
    if (static_cast<unsigned>(i) < static_cast<unsigned>(n)) return i;
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

// One level, nearest or bilinear; texel centers sit at half-integer coordinates.
Vec4 filter_level(const Texture& tex, const TextureImage& img, int level, Vec2 uv, bool nearest) {
    const int w = img.width(level), h = img.height(level);
    const float x = uv.x * w - 0.5f, y = uv.y * h - 0.5f;
    if (nearest) {
        const int ix = wrap(static_cast<int>(std::floor(x + 0.5f)), w, tex.wrap_s);
        const int iy = wrap(static_cast<int>(std::floor(y + 0.5f)), h, tex.wrap_t);
        return img.texel(level, ix, iy);
    }
    const float fx = std::floor(x), fy = std::floor(y);
    const float ax = x - fx, ay = y - fy;
    const int x0 = wrap(static_cast<int>(fx), w, tex.wrap_s);
    const int x1 = wrap(static_cast<int>(fx) + 1, w, tex.wrap_s);
    const int y0 = wrap(static_cast<int>(fy), h, tex.wrap_t);
    const int y1 = wrap(static_cast<int>(fy) + 1, h, tex.wrap_t);
    return img.bilinear(level, x0, x1, y0, y1, ax, ay);
}

Vec4 filtered(const Texture& tex, const TextureImage& img, Vec2 uv, float width) {
    const float lod = texture_lod(img, width);
    if (!(lod > 0)) return filter_level(tex, img, 0, uv, tex.nearest);
    const int top = img.levels() - 1;
    switch (tex.mip) {
        case MipFilter::None:
            return filter_level(tex, img, 0, uv, tex.min_nearest);
        case MipFilter::Nearest:
            return filter_level(tex, img, std::min(top, int(std::lround(lod))), uv,
                                tex.min_nearest);
        case MipFilter::Linear:
        default: {
            if (lod >= float(top)) return filter_level(tex, img, top, uv, tex.min_nearest);
            const int l0 = int(lod);
            const float a = lod - float(l0);
            const Vec4 c0 = filter_level(tex, img, l0, uv, tex.min_nearest);
            if (a == 0) return c0;
            return c0 * (1 - a) + filter_level(tex, img, l0 + 1, uv, tex.min_nearest) * a;
        }
    }
}

}  // namespace

float texture_lod(const TextureImage& img, float width) {
    if (!(width > 0)) return -std::numeric_limits<float>::infinity();
    return std::log2(width * std::sqrt(float(img.width()) * float(img.height())));
}

Vec4 lookup(const Texture& tex, const TextureImage& img, Vec2 uv, float width) {
    if (img.empty()) return {1, 1, 1, 1};
    Vec4 c = std::isfinite(uv.x) && std::isfinite(uv.y) ? filtered(tex, img, uv, width)
                                                        : img.texel(0, 0, 0);
    if (img.color_matrix()) c = Vec4(*img.color_matrix() * c.xyz(), c.w);
    return c;
}

}  // namespace penumbra
