#include "core/denoise/firefly_guard.h"

#include <algorithm>

namespace penumbra {

namespace {

// The largest channel of each pixel.
Planes max_channel(const Planes& p) {
    Planes m(p.width, p.height, 1);
    for (size_t i = 0; i < p.pixels(); ++i)
        m.data[i] = std::max({p.plane(0)[i], p.plane(1)[i], p.plane(2)[i]});
    return m;
}

// The largest value in the 3 x 3 neighbourhood of (x, y), with or without the centre.
float neighbourhood_max(const Planes& m, int x, int y, bool centre) {
    float v = 0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int xq = x + dx, yq = y + dy;
            if ((dx == 0 && dy == 0 && !centre) || xq < 0 || yq < 0 || xq >= m.width ||
                yq >= m.height)
                continue;
            v = std::max(v, m.at(0, xq, yq));
        }
    return v;
}

}  // namespace

size_t guard_fireflies(Planes& a, Planes& b, Planes& variance) {
    const Planes ma = max_channel(a), mb = max_channel(b);
    // In the dark, surroundings near 0 would make every lone sample a firefly: nothing
    // under the image's mean level is held back.
    double level = 0;
    for (size_t i = 0; i < ma.pixels(); ++i) level += double(ma.data[i]) + mb.data[i];
    const float floor = float(level / (2.0 * std::max<size_t>(1, ma.pixels())));
    size_t count = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            bool changed = false;
            for (int half = 0; half < 2; ++half) {
                Planes& own = half == 0 ? a : b;
                const Planes &m_own = half == 0 ? ma : mb, &m_other = half == 0 ? mb : ma;
                const float v = m_own.at(0, x, y);
                const float limit =
                    kFireflyRatio * std::max({floor, neighbourhood_max(m_own, x, y, false),
                                              neighbourhood_max(m_other, x, y, true)});
                if (!(v > limit)) continue;
                const float scale = limit / v;
                for (int c = 0; c < 3; ++c) own.at(c, x, y) *= scale;
                changed = true;
                ++count;
            }
            if (changed)
                for (int c = 0; c < 3; ++c) {
                    const float d = a.at(c, x, y) - b.at(c, x, y);
                    variance.at(c, x, y) = d * d / 4;
                }
        }
    return count;
}

}  // namespace penumbra
