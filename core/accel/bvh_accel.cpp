#include "core/accel/bvh_accel.h"

#include <chrono>

namespace penumbra {

BvhAccel::BvhAccel(const Scene& scene, BvhSplit split) : m_split(split) {
    const auto start = std::chrono::steady_clock::now();
    m_objects.resize(scene.objects.size());
    m_sah_costs.assign(scene.objects.size(), 0.0);
    std::vector<Bounds3> object_bounds(scene.objects.size());
    size_t memory = 0;
    for (size_t oi = 0; oi < scene.objects.size(); ++oi) {
        ObjectBvh& ob = m_objects[oi];
        ob.triangles = gather_object_triangles(scene, scene.objects[oi]);
        std::vector<Bounds3> boxes(ob.triangles.size());
        for (size_t i = 0; i < boxes.size(); ++i) boxes[i] = ob.triangles.triangle_bounds(i);
        BvhTree tree = build_bvh(boxes, split);
        m_sah_costs[oi] = sah_cost(tree);
        ob.triangles.reorder(tree.order);
        ob.nodes = std::move(tree.nodes);
        object_bounds[oi] = ob.triangles.bounds;
        memory += ob.nodes.capacity() * sizeof(BvhNode) + ob.triangles.memory_bytes();
    }
    m_instances = InstanceLevel(scene, object_bounds);

    m_stats.name = "bvh-" + bvh_split_name(split);
    m_stats.build_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    m_stats.object_scenes = m_objects.size();
    m_stats.instances = m_instances.size();
    m_stats.memory_bytes = memory + m_instances.memory_bytes();
}

std::optional<Hit> BvhAccel::do_intersect(const Ray& ray) const {
    Hit best;
    bool found = false;
    float tmax = ray.tmax;
    m_instances.traverse(
        ray, tmax, [&](uint32_t instance, uint32_t object, const Ray& oray, float& t_closest) {
            const ObjectBvh& ob = m_objects[object];
            const RayBoxPrecomp rb(oray);
            const TrianglePrecomp rt(oray);
            Hit h;
            bool here = false;
            const bool deforms = ob.triangles.deforms();
            traverse_bvh(ob.nodes.empty() ? nullptr : ob.nodes.data(), rb, t_closest,
                         [&](uint32_t first, uint32_t count, float& t) {
                             here |= deforms ? ob.triangles.intersect_at(rt, first, count,
                                                                         oray.tmin, &t, &h,
                                                                         oray.time)
                                             : ob.triangles.intersect(rt, first, count,
                                                                      oray.tmin, &t, &h);
                             return false;
                         });
            if (here) {
                best = h;
                best.instance = instance;
                found = true;
            }
            return false;
        });
    if (!found) return std::nullopt;
    return best;
}

bool BvhAccel::do_occluded(const Ray& ray) const {
    bool hit = false;
    float tmax = ray.tmax;
    m_instances.traverse(ray, tmax, [&](uint32_t, uint32_t object, const Ray& oray, float& t0) {
        const ObjectBvh& ob = m_objects[object];
        const RayBoxPrecomp rb(oray);
        const TrianglePrecomp rt(oray);
        float t = t0;
        const bool deforms = ob.triangles.deforms();
        traverse_bvh(ob.nodes.empty() ? nullptr : ob.nodes.data(), rb, t,
                     [&](uint32_t first, uint32_t count, float& tt) {
                         hit = deforms ? ob.triangles.any_hit_at(rt, first, count, oray.tmin,
                                                                 tt, oray.time)
                                       : ob.triangles.any_hit(rt, first, count, oray.tmin, tt);
                         return hit;
                     });
        return hit;
    });
    return hit;
}

}  // namespace penumbra
