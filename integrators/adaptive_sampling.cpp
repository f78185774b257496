#include "integrators/adaptive_sampling.h"

#include <algorithm>
#include <cmath>

namespace penumbra {

uint32_t adaptive_min_spp(double target_error) {
    const double n = std::ceil(16.0 / std::pow(std::max(target_error, 1e-6), 0.3));
    const uint32_t m = uint32_t(std::clamp(n, 8.0, double(1u << 24)));
    return (m + 1) & ~1u;
}

uint32_t adaptive_step(uint32_t done) { return std::max<uint32_t>(16, (done / 4 + 1) & ~1u); }

size_t update_active_pixels(const Film& film, double target_error, std::vector<uint8_t>& active) {
    const int w = film.width(), h = film.height();
    std::vector<double> e2(size_t(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double e = film.relative_error(x, y);
            e2[size_t(y) * w + x] = e * e;
        }
    // Each window's sum and size.
    std::vector<double> sum(e2.size());
    std::vector<int> count(e2.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int u = x + dx, v = y + dy;
                    if (u < 0 || v < 0 || u >= w || v >= h) continue;
                    sum[size_t(y) * w + x] += e2[size_t(v) * w + u];
                    ++count[size_t(y) * w + x];
                }
    const double t2 = target_error * target_error;
    active.assign(e2.size(), 0);
    size_t n_active = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t p = size_t(y) * w + x;
            bool any = false;
            for (int dy = -1; dy <= 1 && !any; ++dy)
                for (int dx = -1; dx <= 1 && !any; ++dx) {
                    const int u = x + dx, v = y + dy;
                    if (u < 0 || v < 0 || u >= w || v >= h) continue;
                    const size_t q = size_t(v) * w + u;
                    any = sum[q] / count[q] >= t2;
                }
            active[p] = any;
            n_active += any;
        }
    return n_active;
}

}  // namespace penumbra
