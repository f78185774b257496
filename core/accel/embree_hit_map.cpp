#include "core/accel/embree_hit_map.h"

namespace penumbra {

EmbreeHitMap::EmbreeHitMap(const Scene& scene)
    : m_scene(&scene),
      m_mesh_ids(scene.objects.size()),
      m_instance_object(scene.instances.size()),
      m_instance_count(static_cast<uint32_t>(scene.instances.size())),
      m_refiner(scene) {
    for (size_t ii = 0; ii < scene.instances.size(); ++ii)
        m_instance_object[ii] = scene.instances[ii].object;
}

void EmbreeHitMap::add_object_mesh(uint32_t object, uint32_t geom_id, uint32_t mesh,
                                   bool keep_planes) {
    std::vector<uint32_t>& ids = m_mesh_ids[object];
    if (ids.size() <= geom_id) ids.resize(geom_id + 1);
    ids[geom_id] = mesh;
    if (keep_planes) m_kept_plane_bytes += m_refiner.keep_planes(mesh);
}

uint32_t EmbreeHitMap::add_flat_mesh(uint32_t instance, uint32_t mesh_index,
                                     const Transform* world) {
    const TriangleMesh& mesh = m_scene->meshes[mesh_index];
    m_facets.push_back(make_facets(mesh, m_scene->instances[instance].to_world));
    m_planes.push_back(world_triangle_planes(mesh, world));
    const std::vector<Facet>& facets = m_facets.back();
    m_record_bytes +=
        facets.size() * sizeof(Facet) + m_planes.back().size() * sizeof(TrianglePlane);
    m_flat.push_back(
        {instance, mesh_index, facets.empty() ? nullptr : facets.data(), m_planes.back().data()});
    return m_instance_count + static_cast<uint32_t>(m_flat.size() - 1);
}

}  // namespace penumbra
