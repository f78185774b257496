// The triangles of one Object (all its meshes) copied out of the scene for our own
// accelerators: three vertices per triangle, stored in the order the accelerator
// chooses, with the ids a Hit reports. Vertex copies keep a leaf's triangles together in
// memory. Triangles of deforming meshes also keep their vertices at every time step and
// are intersected where they are at the ray's time (motion.h's linear rule).
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

// Where a deforming triangle's time steps are: steps * 3 vertices from `first` in
// ObjectTriangles::motion_verts, step-major. steps = 0: the triangle does not deform.
struct TriangleMotion {
    uint32_t first = 0;
    uint32_t steps = 0;
};

struct ObjectTriangles {
    std::vector<Vec3> verts;      // 3 per triangle, object space (step 0 when deforming)
    std::vector<TriangleId> ids;  // 1 per triangle
    Bounds3 bounds;               // of all vertices, at every time step
    // Empty unless a mesh of the object deforms; then 1 per triangle.
    std::vector<TriangleMotion> motion;
    std::vector<Vec3> motion_verts;

    size_t size() const { return ids.size(); }
    bool deforms() const { return !motion.empty(); }
    // Over all time steps: linear interpolation keeps each vertex inside the box of its
    // steps, and the triangle inside the box of its vertices.
    Bounds3 triangle_bounds(size_t i) const {
        Bounds3 b;
        for (int k = 0; k < 3; ++k) b.expand(verts[3 * i + k]);
        if (deforms())
            for (uint32_t k = 0; k < 3 * motion[i].steps; ++k)
                b.expand(motion_verts[motion[i].first + k]);
        return b;
    }
    // Triangle i's vertices at normalized time u.
    void vertices_at(size_t i, float u, Vec3 p[3]) const;
    // Keeps triangles new_order[0], new_order[1], ... in that order.
    void reorder(const std::vector<uint32_t>& new_order);
    size_t memory_bytes() const {
        return verts.capacity() * sizeof(Vec3) + ids.capacity() * sizeof(TriangleId) +
               motion.capacity() * sizeof(TriangleMotion) + motion_verts.capacity() * sizeof(Vec3);
    }
    // A hit on triangle i as every accelerator reports it (all but the instance).
    void record_hit(const TriangleHit& th, uint32_t i, Hit* hit) const {
        hit->t = th.t;
        hit->b1 = th.b1;
        hit->b2 = th.b2;
        hit->mesh = ids[i].mesh;
        hit->prim = ids[i].prim;
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
                record_hit(th, i, hit);
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
    // The same for objects that deform (deforms()), with the triangles at time u. Separate
    // functions so that static objects keep the loops above unchanged.
    bool intersect_at(const TrianglePrecomp& r, uint32_t first, uint32_t count, float tmin,
                      float* tmax, Hit* hit, float u) const {
        bool found = false;
        for (uint32_t i = first; i < first + count; ++i) {
            Vec3 p[3];
            vertices_at(i, u, p);
            TriangleHit th;
            if (intersect_triangle(r, p[0], p[1], p[2], tmin, *tmax, &th)) {
                *tmax = th.t;
                record_hit(th, i, hit);
                found = true;
            }
        }
        return found;
    }
    bool any_hit_at(const TrianglePrecomp& r, uint32_t first, uint32_t count, float tmin,
                    float tmax, float u) const {
        TriangleHit th;
        for (uint32_t i = first; i < first + count; ++i) {
            Vec3 p[3];
            vertices_at(i, u, p);
            if (intersect_triangle(r, p[0], p[1], p[2], tmin, tmax, &th)) return true;
        }
        return false;
    }
};

// Triangles with a non-finite vertex are left out (Embree ignores them too). Zero-area
// triangles stay: the intersection test rejects them (det = 0).
ObjectTriangles gather_object_triangles(const Scene& scene, const Object& object);

}  // namespace penumbra
