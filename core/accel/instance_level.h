// The top level of our two-level accelerators (BVH and grid): a BVH over the instances'
// world boxes. An instance maps the world ray into its object's space with the inverse
// of its transform, without renormalizing the direction, so a t found in object space
// is the world t ("TransformedSurface"); many instances share one object structure.
// A moving instance's transform is interpolated at ray.time (motion.h, as Embree does)
// and its box encloses the whole motion.
#pragma once

#include <cstdint>
#include <vector>

#include "core/accel/bvh_traverse.h"
#include "core/accel/instance_transform.h"
#include "core/scene/motion.h"
#include "core/scene/scene.h"

namespace penumbra {

class InstanceLevel {
public:
    InstanceLevel() = default;
    // object_bounds[i]: object-space bounds of Scene::objects[i] as the accelerator
    // stores it; instances of objects with empty bounds are left out.
    InstanceLevel(const Scene& scene, const std::vector<Bounds3>& object_bounds);

    // Calls visit(instance, object, object_ray, tmax) for each instance whose world box
    // the ray reaches within [ray.tmin, tmax], nearer boxes first. visit may shrink tmax
    // and returns true to stop.
    template <class Visit>
    void traverse(const Ray& ray, float& tmax, Visit&& visit) const {
        const RayBoxPrecomp r(ray);
        traverse_bvh(m_tree.nodes.empty() ? nullptr : m_tree.nodes.data(), r, tmax,
                     [&](uint32_t first, uint32_t count, float& t) {
                         for (uint32_t i = first; i < first + count; ++i) {
                             const Record& rec = m_records[i];
                             if (visit(rec.instance, rec.object, object_ray(rec, ray), t))
                                 return true;
                         }
                         return false;
                     });
    }
    size_t size() const { return m_records.size(); }
    size_t memory_bytes() const {
        size_t motion = 0;
        for (const auto& m : m_motion) motion += m.capacity() * sizeof(QuatDecomposition);
        return m_tree.nodes.capacity() * sizeof(BvhNode) + m_records.capacity() * sizeof(Record) +
               motion;
    }

private:
    // A static instance keeps its world-to-object map (instance_transform.h), a moving
    // one its decomposed time steps. With a float inverse, on scenes/instances.gltf the
    // rounding alone put ~1 in 100,000 rays on the other side of an edge.
    static constexpr uint32_t kStatic = ~0u;
    struct Record {
        WorldToObject to_object;    // static: the inverse of the affine part
        uint32_t instance;          // Scene::instances index
        uint32_t object;            // Scene::objects index
        uint32_t motion = kStatic;  // index into m_motion, or kStatic
    };
    Ray object_ray(const Record& rec, const Ray& ray) const {
        if (rec.motion != kStatic) return moving_object_ray(m_motion[rec.motion], ray);
        return transform_ray(rec.to_object, ray);
    }

    BvhTree m_tree;
    std::vector<Record> m_records;  // in the tree's leaf order
    std::vector<std::vector<QuatDecomposition>> m_motion;
};

}  // namespace penumbra
