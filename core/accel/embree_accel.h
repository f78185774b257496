// Embree 3 traversal: one Embree scene per Object (each TriangleMesh a geometry), and a
// top-level scene with one instance geometry per Instance. Embree types stay in the .cpp.
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

}  // namespace penumbra
