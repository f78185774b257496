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

// The median of the values around (x, y): its 8 neighbours in its own half and the 9
// pixels at and around it in the other. A median, not a maximum, so that fireflies next
// to each other (dense where caustics are) do not shield each other.
float surroundings(const Planes& own, const Planes& other, int x, int y) {
    float v[17];
    int n = 0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int xq = x + dx, yq = y + dy;
            if (xq < 0 || yq < 0 || xq >= own.width || yq >= own.height) continue;
            if (dx != 0 || dy != 0) v[n++] = own.at(0, xq, yq);
            v[n++] = other.at(0, xq, yq);
        }
    std::nth_element(v, v + n / 2, v + n);
    return v[n / 2];
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
                // The other half's own value keeps a real small bright feature, which
                // both halves show at the same pixel.
                const float limit =
                    kFireflyRatio *
                    std::max({floor, surroundings(m_own, m_other, x, y), m_other.at(0, x, y)});
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
