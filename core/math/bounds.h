// Axis-aligned bounding boxes. An empty box has min = +inf and max = -inf so that
// expanding it by any point gives that point.
#pragma once

#include <limits>

#include "core/math/vec.h"

namespace penumbra {

struct Bounds3 {
    Vec3 lo{std::numeric_limits<float>::infinity()};
    Vec3 hi{-std::numeric_limits<float>::infinity()};

    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    void expand(Vec3 p) { lo = min(lo, p); hi = max(hi, p); }
    void expand(const Bounds3& b) { lo = min(lo, b.lo); hi = max(hi, b.hi); }
    Vec3 center() const { return (lo + hi) * 0.5f; }
    Vec3 diagonal() const { return hi - lo; }
};

}  // namespace penumbra
