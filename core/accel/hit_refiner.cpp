#include "core/accel/hit_refiner.h"

namespace penumbra {

HitRefiner::HitRefiner(const Scene& scene) : m_scene(&scene), m_planes(scene.meshes.size()) {
    m_placements.resize(scene.instances.size());
    for (size_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& inst = scene.instances[i];
        Placement& pl = m_placements[i];
        pl.to_object = world_to_object(inst.to_world.matrix());
        pl.identity = inst.motion.empty() && inst.to_world.matrix().is_identity();
        if (!inst.motion.empty()) {
            pl.motion = static_cast<uint32_t>(m_motion.size());
            m_motion.push_back(decompose_steps(inst.motion));
        }
    }
}

bool HitRefiner::plane_hit(const Ray& ray, uint32_t instance, uint32_t mesh_index, uint32_t prim,
                           TriangleHit* hit) const {
    const std::vector<TrianglePlane>& kept = m_planes[mesh_index];
    TrianglePlane plane;
    if (!kept.empty()) {
        plane = kept[prim];
    } else {
        const TriangleMesh& mesh = m_scene->meshes[mesh_index];
        const uint32_t* idx = &mesh.indices[3 * size_t(prim)];
        Vec3 p[3];
        if (mesh.motion_positions.empty()) {
            for (int k = 0; k < 3; ++k) p[k] = mesh.positions[idx[k]];
        } else {
            for (int k = 0; k < 3; ++k) p[k] = position_at(mesh, idx[k], ray.time);
        }
        plane = make_triangle_plane(p[0], p[1], p[2]);
    }
    const Placement& pl = m_placements[instance];
    if (pl.identity) return triangle_plane_hit(plane, ray, hit);
    const Ray oray = pl.motion == kStatic ? transform_ray(pl.to_object, ray)
                                          : moving_object_ray(m_motion[pl.motion], ray);
    return triangle_plane_hit(plane, oray, hit);
}

size_t HitRefiner::keep_planes(uint32_t mesh_index) {
    const TriangleMesh& mesh = m_scene->meshes[mesh_index];
    std::vector<TrianglePlane>& kept = m_planes[mesh_index];
    if (!mesh.motion_positions.empty() || !kept.empty()) return 0;
    kept = world_triangle_planes(mesh, nullptr);
    return kept.size() * sizeof(TrianglePlane);
}

std::vector<TrianglePlane> world_triangle_planes(const TriangleMesh& mesh,
                                                 const Transform* to_world) {
    std::vector<TrianglePlane> planes(mesh.triangle_count());
    for (size_t i = 0; i < planes.size(); ++i) {
        Vec3 p[3];
        for (int k = 0; k < 3; ++k) {
            p[k] = mesh.positions[mesh.indices[3 * i + k]];
            if (to_world) p[k] = to_world->point(p[k]);
        }
        planes[i] = make_triangle_plane(p[0], p[1], p[2]);
    }
    return planes;
}

}  // namespace penumbra
