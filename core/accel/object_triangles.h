// The triangles of one Object (all its meshes) copied out of the scene for our own
// accelerators: three vertices per triangle, stored in the order the accelerator
// chooses, with the ids a Hit reports. Vertex copies keep a leaf's triangles together in
// memory; with motion, one such vertex array per time step will sit beside the ids.
#pragma once

#include <cstdint>
#include <vector>

#include "core/accel/triangle_intersect.h"
#include "core/scene/scene.h"

namespace penumbra {

struct TriangleId {
    uint32_t mesh;  // Scene::meshes index
    uint32_t prim;  // triangle index within that mesh
};

struct ObjectTriangles {
    std::vector<Vec3> verts;      // 3 per triangle, object space
    std::vector<TriangleId> ids;  // 1 per triangle
    Bounds3 bounds;               // of all vertices

    size_t size() const { return ids.size(); }
    Bounds3 triangle_bounds(size_t i) const {
        Bounds3 b;
        for (int k = 0; k < 3; ++k) b.expand(verts[3 * i + k]);
        return b;
    }
    // Keeps triangles new_order[0], new_order[1], ... in that order.
    void reorder(const std::vector<uint32_t>& new_order);
    size_t memory_bytes() const {
        return verts.capacity() * sizeof(Vec3) + ids.capacity() * sizeof(TriangleId);
    }
    // Closest hit among triangles [first, first + count) in [tmin, *tmax]; on a hit,
    // shrinks *tmax and fills *hit (all but the instance).
    bool intersect(const TrianglePrecomp& r, uint32_t first, uint32_t count, float tmin,
                   float* tmax, Hit* hit) const {
        bool found = false;
        for (uint32_t i = first; i < first + count; ++i) {
            TriangleHit th;
            if (intersect_triangle(r, verts[3 * i], verts[3 * i + 1], verts[3 * i + 2], tmin, *tmax,
                                   &th)) {
                *tmax = th.t;
                hit->t = th.t;
                hit->b1 = th.b1;
                hit->b2 = th.b2;
                hit->mesh = ids[i].mesh;
                hit->prim = ids[i].prim;
                found = true;
            }
        }
        return found;
    }
    bool any_hit(const TrianglePrecomp& r, uint32_t first, uint32_t count, float tmin,
                 float tmax) const {
        TriangleHit th;
        for (uint32_t i = first; i < first + count; ++i)
            if (intersect_triangle(r, verts[3 * i], verts[3 * i + 1], verts[3 * i + 2], tmin, tmax,
                                   &th))
                return true;
        return false;
    }
};

// Triangles with a non-finite vertex are left out (Embree ignores them too). Zero-area
// triangles stay: the intersection test rejects them (det = 0).
ObjectTriangles gather_object_triangles(const Scene& scene, const Object& object);

}  // namespace penumbra
