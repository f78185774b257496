// From the ids of an Embree hit record to our Hit: which Scene instance, mesh and
// triangle Embree's instID, geomID and primID name, and where the ray meets that triangle,
// recomputed with our own arithmetic so that no reported value depends on the code path
// Embree ran. No Embree types: EmbreeAccel passes the record's fields.
#pragma once

#include <cstdint>
#include <vector>

#include "core/accel/hit_refiner.h"
#include "core/accel/triangle_plane.h"
#include "core/facet.h"
#include "core/scene/scene.h"

namespace penumbra {

class EmbreeHitMap {
public:
    // Embree's RTC_INVALID_GEOMETRY_ID: a hit in the top-level scene has this instID.
    static constexpr uint32_t kNoInstance = ~0u;

    EmbreeHitMap() = default;
    // The scene must outlive the map. Top-level geomIDs below instance count are
    // instances; flattened meshes follow (add_flat_mesh).
    explicit EmbreeHitMap(const Scene& scene);
    // The same geometry in another Scene object (Accel::rebind).
    void rebind(const Scene& scene) {
        m_scene = &scene;
        m_refiner.rebind(scene);
    }

    // geomID geom_id of object `object`'s Embree scene is Scene mesh `mesh`; keep_planes:
    // precompute its triangles' planes (HitRefiner::keep_planes).
    void add_object_mesh(uint32_t object, uint32_t geom_id, uint32_t mesh, bool keep_planes);
    // A flattened copy of Scene mesh `mesh` placed by instance `instance` (world: the
    // placement its vertices were transformed by, nullptr: none), with its triangles'
    // facets and planes; returns the top-level geomID it must be attached with.
    uint32_t add_flat_mesh(uint32_t instance, uint32_t mesh, const Transform* world);

    // Bytes of the flattened meshes' facets and planes (EmbreeAccel::facet_bytes).
    size_t record_bytes() const { return m_record_bytes; }
    // Bytes of the instanced meshes' kept planes (add_object_mesh).
    size_t kept_plane_bytes() const { return m_kept_plane_bytes; }

    // The Hit of an Embree hit record. Embree picks the triangle; where the ray meets it
    // is recomputed (a flattened mesh's precomputed plane, else refine), so that no
    // reported value depends on which code path Embree ran.
    Hit hit(const Ray& ray, uint32_t inst_id, uint32_t geom_id, uint32_t prim, float u, float v,
            float t) const {
        Hit h;
        h.t = t;
        h.prim = prim;
        h.b1 = u;
        h.b2 = v;
        if (inst_id == kNoInstance) {
            const FlatMesh& ids = m_flat[geom_id - m_instance_count];
            h.instance = ids.instance;
            h.mesh = ids.mesh;
            if (ids.facets) h.facet = ids.facets + prim;
            TriangleHit th;
            if (triangle_plane_hit(ids.planes[prim], ray, &th)) set(th, &h);
        } else {
            h.instance = inst_id;
            h.mesh = m_mesh_ids[m_instance_object[inst_id]][geom_id];
            refine(ray, &h);
        }
        return h;
    }

private:
    static void set(const TriangleHit& th, Hit* h) {
        h->t = th.t;
        h->b1 = th.b1;
        h->b2 = th.b2;
    }

    // Embree computes t, u and v in float with approximate reciprocals (RCPPS, whose bits
    // differ between CPU vendors) and with or without FMA, by ISA; a moving instance's
    // transform also with approximate square roots. They are recomputed with our own
    // arithmetic: on a flattened mesh's world-space triangle as Embree traces it (its
    // precomputed plane), else by the refiner. Where that has no answer (a ray parallel to
    // the triangle in float), Embree's values stay.
    void refine(const Ray& ray, Hit* h) const {
        TriangleHit th;
        if (m_refiner.plane_hit(ray, h->instance, h->mesh, h->prim, &th)) set(th, h);
    }

    // A flattened mesh: its facets (null for a mesh whose normals move) and the planes of
    // its world-space triangles as Embree traces them.
    struct FlatMesh {
        uint32_t instance, mesh;
        const Facet* facets;
        const TrianglePlane* planes;
    };
    const Scene* m_scene = nullptr;
    std::vector<std::vector<uint32_t>> m_mesh_ids;  // object, geomID -> Scene::meshes index
    std::vector<uint32_t> m_instance_object;        // instID -> object index
    uint32_t m_instance_count = 0;
    std::vector<FlatMesh> m_flat;  // top-level geomID - instance count
    HitRefiner m_refiner;          // instanced triangles
    // The flattened meshes' facets: per hit on them, make_surface_point reads the world
    // normal and the flat-shading flag instead of recomputing them (16 bytes a triangle,
    // within EmbreeBuildOptions::flatten_budget triangles).
    std::vector<std::vector<Facet>> m_facets;
    // And their triangles' planes, for refining: 48 bytes a triangle, which save building
    // the plane from the vertices at every hit (docs/performance-traversal.md, "Hits recomputed
    // from Embree's choice of triangle").
    std::vector<std::vector<TrianglePlane>> m_planes;
    size_t m_record_bytes = 0;
    size_t m_kept_plane_bytes = 0;
};

}  // namespace penumbra
