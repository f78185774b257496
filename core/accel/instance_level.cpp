#include "core/accel/instance_level.h"

#include <algorithm>
#include <cmath>

namespace penumbra {

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
        rec.to_object = world_to_object(inst.to_world.matrix());
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

}  // namespace penumbra
