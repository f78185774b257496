// A uniform grid per Object, walked cell by cell with the 3D-DDA of Amanatides & Woo
// (1987, "A Fast Voxel Traversal Algorithm for Ray Tracing"), under the same instance
// level as the BVH. The classic course accelerator, kept as a third opinion.
#pragma once

#include <vector>

#include "core/accel/accel.h"
#include "core/accel/instance_level.h"
#include "core/accel/object_triangles.h"

namespace penumbra {

class GridAccel final : public Accel {
public:
    explicit GridAccel(const Scene& scene);
    AccelStats stats() const override { return m_stats; }

    // Cells per axis for n triangles in a box of the given extent: 3 cbrt(n) along the
    // longest axis (the rule of pbrt's first-edition GridAccel: about 27n cells for a
    // cube, which leaves a few triangles per non-empty cell of a closed surface, whose
    // triangles occupy O(n^(2/3)) of the cells), the other axes in proportion, each
    // axis at least 1 and at most kMaxGridRes.
    static constexpr int kMaxGridRes = 256;
    static void resolution(size_t n, Vec3 extent, int res[3]);

protected:
    std::optional<Hit> do_intersect(const Ray& ray) const override;
    bool do_occluded(const Ray& ray) const override;

private:
    struct ObjectGrid {
        Bounds3 box;  // the triangles' bounds, padded so no axis is flat
        int res[3] = {1, 1, 1};
        Vec3 cell_size, inv_cell_size;
        std::vector<uint32_t> cell_start;  // CSR: cell c holds refs[cell_start[c] ..
        std::vector<uint32_t> refs;        //   cell_start[c + 1]), triangle indices
        ObjectTriangles triangles;
    };
    template <bool kAnyHit>
    static bool walk(const ObjectGrid& g, const Ray& ray, float* tmax, Hit* hit);
    static ObjectGrid build_grid(ObjectTriangles triangles);

    std::vector<ObjectGrid> m_objects;
    InstanceLevel m_instances;
    AccelStats m_stats;
};

}  // namespace penumbra
