// Embree 3 traversal: one Embree scene per Object (each TriangleMesh a geometry), and a
// top-level scene with one instance geometry per Instance. Embree types stay in the .cpp.
// Moving instances and deforming meshes get Embree time steps; static ones none.
#pragma once

#include <memory>
#include <vector>

#include "core/accel/accel.h"

namespace penumbra {

class EmbreeAccel final : public Accel {
public:
    explicit EmbreeAccel(const Scene& scene);
    ~EmbreeAccel() override;
    AccelStats stats() const override { return m_stats; }

protected:
    std::optional<Hit> do_intersect(const Ray& ray) const override;
    bool do_occluded(const Ray& ray) const override;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
    AccelStats m_stats;
};

// The transform Embree itself computes at time u for an instance with these time steps
// (rtcGetGeometryTransform), to check motion.h against Embree directly.
Mat4 embree_transform_at(const std::vector<Transform>& steps, float u);

}  // namespace penumbra
