// Where a ray meets a triangle that another accelerator (Embree) has chosen, computed
// with our own arithmetic: t and the barycentrics of a hit then do not depend on which
// instruction set, CPU vendor or approximate reciprocal the traversal used. The ray is
// mapped into the instance's object space as BvhAccel maps it (instance_transform.h),
// a deforming triangle taken at the ray's time, and triangle_plane_hit (triangle_plane.h)
// does the rest.
#pragma once

#include <cstdint>
#include <vector>

#include "core/accel/instance_transform.h"
#include "core/accel/triangle_plane.h"
#include "core/scene/scene.h"

namespace penumbra {

class HitRefiner {
public:
    HitRefiner() = default;
    // The scene must outlive the refiner.
    explicit HitRefiner(const Scene& scene);
    // The same geometry in another Scene object (Accel::rebind).
    void rebind(const Scene& scene) { m_scene = &scene; }

    // Triangle prim of Scene mesh `mesh`, placed by Scene instance `instance`, met by the
    // world-space ray. False where the ray is parallel to the triangle in float.
    bool plane_hit(const Ray& ray, uint32_t instance, uint32_t mesh, uint32_t prim,
                   TriangleHit* hit) const;

    // Precomputes the object-space planes of Scene mesh `mesh` (48 bytes a triangle), which
    // its hits then read instead of building each from the vertices: the same planes, so
    // the same bits. Returns their bytes: 0 for a deforming mesh or one already kept.
    size_t keep_planes(uint32_t mesh);

private:
    static constexpr uint32_t kStatic = ~0u;
    struct Placement {
        WorldToObject to_object;
        uint32_t motion = kStatic;  // index into m_motion, or kStatic
        bool identity = false;      // static and the identity: the world ray as it is
    };
    const Scene* m_scene = nullptr;
    std::vector<Placement> m_placements;  // per Scene instance
    std::vector<std::vector<QuatDecomposition>> m_motion;
    std::vector<std::vector<TrianglePlane>> m_planes;  // per Scene mesh; empty: not kept
};

// The planes of a static mesh's triangles placed by to_world (nullptr: as they are),
// each vertex transformed by Transform::point, as a flattened copy of the mesh has it.
std::vector<TrianglePlane> world_triangle_planes(const TriangleMesh& mesh,
                                                 const Transform* to_world);

}  // namespace penumbra
