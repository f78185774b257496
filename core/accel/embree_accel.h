// Embree 3 traversal: a top-level scene holding the triangles of small static objects in
// world space (instancing does not pay for them), and one instance geometry per other
// Instance, of a per-Object scene. Embree types stay in the .cpp. Moving instances
// and deforming meshes get Embree time steps; static ones none. Embree reads the scene's
// index and (where padded) vertex arrays in place: the Scene must outlive the accelerator
// and keep its meshes unchanged.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/accel/accel.h"

namespace penumbra {

// How Embree builds its BVHs (rtcSetSceneBuildQuality, RTC_SCENE_FLAG_COMPACT); the
// defaults are Embree's, measured against the others in docs/performance.md ("Big scenes").
struct EmbreeBuildOptions {
    enum class Quality { Low, Medium, High };
    Quality quality = Quality::Medium;
    bool compact = false;  // leaves index the vertex arrays: less memory, slower rays
    // One level where instancing buys nothing: a rigid Object with only static
    // placements goes into the top-level scene as world-space triangles when its
    // triangles times its placements are at most flatten_triangles (and the sum of such
    // copies stays within flatten_budget), so that a ray traverses one BVH as in
    // Embree's tutorials. Larger objects keep their own BVH even when placed once: one
    // top-level build over all of them doubles build CPU and adds 24% to the peak
    // memory of a 2M-triangle scene (docs/performance.md). false: two levels everywhere.
    bool flatten = true;
    size_t flatten_triangles = 65536;
    size_t flatten_budget = size_t(1) << 20;
    // Embree's device config string (rtcNewDevice), e.g. "isa=sse4.2"; empty: the
    // environment's PENUMBRA_EMBREE_CONFIG, if set.
    std::string device_config;
};

class EmbreeAccel final : public Accel {
public:
    explicit EmbreeAccel(const Scene& scene, const EmbreeBuildOptions& options = {});
    ~EmbreeAccel() override;
    AccelStats stats() const override { return m_stats; }
    void rebind(const Scene& scene) override;
    // Vertex bytes copied out of the Scene: positions without a spare element of
    // capacity, and the world-space copies of flattened objects (0 when Embree reads
    // every array in place).
    size_t copied_bytes() const { return m_copied_bytes; }
    // Scene instances traced as world-space triangles of the top level
    // (EmbreeBuildOptions::flatten); stats().instances counts the others.
    size_t flattened() const { return m_flattened; }
    // Bytes of the flattened triangles' precomputed facets (core/facet.h: 16 per triangle
    // and placement), which their hits point to, and planes (triangle_plane.h: 48),
    // which refine their hits; bounded by flatten_budget triangles.
    size_t facet_bytes() const { return m_facet_bytes; }
    // Eight closest-hit queries as one rtcIntersect8 packet (hits[i] empty: a miss or an
    // untraceable ray); for coherent batches such as a 4 x 2 block of camera rays.
    // bench/accel_bench.cpp measures it against intersect().
    void intersect8(const Ray (&rays)[8], std::optional<Hit> (&hits)[8]) const override;
    // n shadow-ray queries as one rtcOccluded1M stream; coherent sets Embree's hint.
    void occluded_stream(const Ray* rays, size_t n, bool* occluded, bool coherent) const;

    struct Impl;  // Embree's objects and our ids; defined in the .cpp

protected:
    std::optional<Hit> do_intersect(const Ray& ray) const override;
    bool do_occluded(const Ray& ray) const override;

private:
    // rtcIntersect1, with refined_t_filter (embree_accel.cpp) when filtered.
    std::optional<Hit> closest_hit(const Ray& ray, bool filtered) const;

    std::unique_ptr<Impl> m_impl;
    AccelStats m_stats;
    size_t m_copied_bytes = 0;
    size_t m_flattened = 0;
    size_t m_facet_bytes = 0;
};

// The transform Embree itself computes at time u for an instance with these time steps
// (rtcGetGeometryTransform), to check motion.h against Embree directly.
Mat4 embree_transform_at(const std::vector<Transform>& steps, float u);

}  // namespace penumbra
