// Our reference accelerator: one BVH per Object over all its meshes' triangles, and the
// instance level (instance_level.h) above them, like the Embree path. Scalar code, single
// rays; it exists to be read and to cross-check Embree, not to beat it.
#pragma once

#include <vector>

#include "core/accel/accel.h"
#include "core/accel/bvh_build.h"
#include "core/accel/instance_level.h"
#include "core/accel/object_triangles.h"

namespace penumbra {

class BvhAccel final : public Accel {
public:
    explicit BvhAccel(const Scene& scene, BvhSplit split = BvhSplit::Sah);
    AccelStats stats() const override { return m_stats; }
    BvhSplit split() const { return m_split; }
    // SAH expected cost (bvh_build.h) of each object's tree, Scene::objects order.
    const std::vector<double>& object_sah_costs() const { return m_sah_costs; }

protected:
    std::optional<Hit> do_intersect(const Ray& ray) const override;
    bool do_occluded(const Ray& ray) const override;

private:
    struct ObjectBvh {
        std::vector<BvhNode> nodes;
        ObjectTriangles triangles;  // in leaf order
    };
    BvhSplit m_split;
    std::vector<ObjectBvh> m_objects;
    std::vector<double> m_sah_costs;
    InstanceLevel m_instances;
    AccelStats m_stats;
};

}  // namespace penumbra
