// Rays and the record of a ray's closest hit, shared by every accelerator.
#pragma once

#include <cstdint>
#include <limits>

#include "core/math/vec.h"
#include "core/ray_cone.h"

namespace penumbra {

struct Facet;

struct Ray {
    Vec3 o;
    Vec3 d;  // not necessarily unit length; t is measured in units of |d|
    float tmin = 0;
    float tmax = std::numeric_limits<float>::infinity();
    float time = 0;  // normalized shutter time in [0, 1]
    RayCone cone;    // texture footprint (camera rays and their bounces; none: a point)
};

// The closest hit as every accelerator reports it: enough to rebuild the surface point
// (see surface_point.h) and nothing accelerator-specific (the facet only caches values
// the rest implies).
struct Hit {
    float t = 0;
    uint32_t instance = 0;  // index into Scene::instances
    uint32_t mesh = 0;      // index into Scene::meshes (one glTF primitive)
    uint32_t prim = 0;      // triangle index within the mesh
    float b1 = 0, b2 = 0;   // barycentrics of vertices 1 and 2
    // The triangle's precomputed facet (core/facet.h) where the accelerator keeps one
    // (EmbreeAccel: flattened objects); null: make_surface_point computes the values.
    const Facet* facet = nullptr;
};

}  // namespace penumbra
