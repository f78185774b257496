#include "io/gltf/animation/gltf_property_animation.h"

namespace penumbra {

bool changes_within(const std::vector<PropertyChannel>& channels, const Shutter& shutter) {
    if (shutter.still()) return false;
    const double a = shutter.open, b = shutter.close;
    for (const PropertyChannel& ch : channels) {
        const std::vector<double>& t = ch.curve->times;
        // Clamped outside its keys, a curve is constant there.
        if (t.size() < 2 || b <= t.front() || a >= t.back()) continue;
        // The keys inside the shutter, its close, and points between (a CUBICSPLINE
        // curve can leave and come back between equal keys).
        std::vector<double> when = {b};
        for (double k : t)
            if (k > a && k < b) when.push_back(k);
        for (int i = 1; i < 16; ++i) when.push_back(a + (b - a) * i / 16);
        const std::vector<double> first = ch.curve->sample(a);
        for (double w : when)
            if (ch.curve->sample(w) != first) return true;
    }
    return false;
}

}  // namespace penumbra
