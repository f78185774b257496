#include "core/accel/instance_level.h"

#include <algorithm>
#include <cmath>

namespace penumbra {

namespace {

// Inverse of the affine part [A | t] of m in double: [A^-1 | -A^-1 t], A^-1 by cofactors.
void invert_affine(const Mat4& m, double out[3][4]) {
    double a[3][3];
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) a[r][c] = m(r, c);
    const double c00 = a[1][1] * a[2][2] - a[1][2] * a[2][1];
    const double c01 = a[1][2] * a[2][0] - a[1][0] * a[2][2];
    const double c02 = a[1][0] * a[2][1] - a[1][1] * a[2][0];
    const double det = a[0][0] * c00 + a[0][1] * c01 + a[0][2] * c02;
    const double s = 1.0 / det;  // Transform guarantees a non-singular matrix
    out[0][0] = c00 * s;
    out[1][0] = c01 * s;
    out[2][0] = c02 * s;
    out[0][1] = (a[0][2] * a[2][1] - a[0][1] * a[2][2]) * s;
    out[1][1] = (a[0][0] * a[2][2] - a[0][2] * a[2][0]) * s;
    out[2][1] = (a[0][1] * a[2][0] - a[0][0] * a[2][1]) * s;
    out[0][2] = (a[0][1] * a[1][2] - a[0][2] * a[1][1]) * s;
    out[1][2] = (a[0][2] * a[1][0] - a[0][0] * a[1][2]) * s;
    out[2][2] = (a[0][0] * a[1][1] - a[0][1] * a[1][0]) * s;
    for (int r = 0; r < 3; ++r)
        out[r][3] = -(out[r][0] * m(0, 3) + out[r][1] * m(1, 3) + out[r][2] * m(2, 3));
}

}  // namespace

InstanceLevel::InstanceLevel(const Scene& scene, const std::vector<Bounds3>& object_bounds) {
    std::vector<Bounds3> boxes;
    std::vector<Record> records;
    for (size_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& inst = scene.instances[i];
        const Bounds3& ob = object_bounds[inst.object];
        if (ob.empty()) continue;
        Record rec;
        rec.instance = static_cast<uint32_t>(i);
        rec.object = inst.object;
        invert_affine(inst.to_world.matrix(), rec.to_object);
        Bounds3 wb;
        if (inst.motion.empty()) {
            wb = inst.to_world.bounds(ob);
        } else {
            rec.motion = static_cast<uint32_t>(m_motion.size());
            m_motion.push_back(decompose_steps(inst.motion));
            wb = motion_bounds(m_motion.back(), ob);
        }
        // The corners are transformed in float: pad the box by a few ulps of its largest
        // coordinate so that rounding cannot cull a hit on the object's own boundary.
        float scale = 0;
        for (int a = 0; a < 3; ++a)
            scale = std::max({scale, std::abs(wb.lo[a]), std::abs(wb.hi[a])});
        const Vec3 pad(scale * 0x1p-20f);
        wb.lo -= pad;
        wb.hi += pad;
        if (!is_finite(wb.lo) || !is_finite(wb.hi)) continue;
        boxes.push_back(wb);
        records.push_back(rec);
    }
    m_tree = build_bvh(boxes, BvhSplit::Sah);
    m_records.resize(records.size());
    for (size_t i = 0; i < m_tree.order.size(); ++i) m_records[i] = records[m_tree.order[i]];
}

Ray InstanceLevel::moving_object_ray(const Record& rec, const Ray& ray) const {
    double m[3][4];
    invert_affine(motion_matrix_at(m_motion[rec.motion], ray.time), m);
    return transform_ray(m, ray);
}

}  // namespace penumbra
