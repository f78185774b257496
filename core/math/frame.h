// Orthonormal shading frames. Local coordinates have z along the normal, so
// cos(theta) = w.z; BSDFs work in this frame and the integrator converts.
#pragma once

#include <cmath>

#include "core/math/vec.h"

namespace penumbra {

struct Frame {
    Vec3 s, t, n;

    Frame() : s(1, 0, 0), t(0, 1, 0), n(0, 0, 1) {}
    Frame(Vec3 s_, Vec3 t_, Vec3 n_) : s(s_), t(t_), n(n_) {}
    // Branchless basis from a unit normal (Duff et al. 2017, "Building an Orthonormal
    // Basis, Revisited"), free of the singularity of the cross-product construction.
    static Frame from_normal(Vec3 n) {
        const float sign = std::copysign(1.0f, n.z);
        const float a = -1.0f / (sign + n.z);
        const float b = n.x * n.y * a;
        return Frame(Vec3(1 + sign * n.x * n.x * a, sign * b, -sign * n.x),
                     Vec3(b, sign + n.y * n.y * a, -n.y), n);
    }
    // Gram-Schmidt: a frame around n whose s follows the tangent direction.
    static Frame from_normal_tangent(Vec3 n, Vec3 tangent) {
        Vec3 s = tangent - n * dot(n, tangent);
        const float len2 = length_squared(s);
        if (!(len2 > 1e-12f)) return from_normal(n);
        s = s / std::sqrt(len2);
        return Frame(s, cross(n, s), n);
    }
    Vec3 to_local(Vec3 v) const { return {dot(v, s), dot(v, t), dot(v, n)}; }
    Vec3 to_world(Vec3 v) const { return s * v.x + t * v.y + n * v.z; }
};

}  // namespace penumbra
