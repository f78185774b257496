// World-to-object maps of instances, as every accelerator applies them to a ray: the
// inverse of the instance's affine matrix, kept and applied in double, so that the
// object-space ray is the world ray rounded once; for a moving instance, its matrix at
// ray.time built in float as Embree builds it (motion.h), then inverted in double. The
// direction is not renormalized, so a t found in object space is the world t.
#pragma once

#include <vector>

#include "core/math/transform.h"
#include "core/ray.h"
#include "core/scene/motion.h"

namespace penumbra {

// Rows of the inverse of an affine map's [A | t]: [A^-1 | -A^-1 t].
struct WorldToObject {
    double m[3][4];
};

// The inverse of m's affine part, in double (A^-1 by cofactors); m must be non-singular,
// as Transform guarantees.
WorldToObject world_to_object(const Mat4& m);

// The ray through the rows of an affine world-to-object map, in double, rounded once.
inline Ray transform_ray(const WorldToObject& w, const Ray& ray) {
    const auto& m = w.m;
    Ray r = ray;
    for (int i = 0; i < 3; ++i) {
        r.o[i] =
            static_cast<float>(m[i][0] * ray.o.x + m[i][1] * ray.o.y + m[i][2] * ray.o.z + m[i][3]);
        r.d[i] = static_cast<float>(m[i][0] * ray.d.x + m[i][1] * ray.d.y + m[i][2] * ray.d.z);
    }
    return r;
}

// The ray in the object space of a moving instance with these decomposed time steps, at
// the ray's time.
Ray moving_object_ray(const std::vector<QuatDecomposition>& steps, const Ray& ray);

}  // namespace penumbra
