#include "core/media/medium_set.h"

#include <algorithm>
#include <cmath>

#include "core/media/homogeneous_medium.h"

namespace penumbra {

bool material_has_volume(const MaterialDesc& m) { return m.thickness > 0; }

MediumSet::MediumSet(const Scene& scene) : m_media(scene.materials.size()) {
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        const MaterialDesc& m = scene.materials[i];
        if (!material_has_volume(m)) continue;
        m_media[i] = std::make_shared<HomogeneousMedium>(HomogeneousMedium::sigma_a_from_attenuation(
            m.attenuation_color, m.attenuation_distance));
    }
    if (!any()) return;
    m_bounds.resize(scene.instances.size());
    for (size_t ii = 0; ii < scene.instances.size(); ++ii) {
        const Instance& inst = scene.instances[ii];
        if (!inst.motion.empty()) continue;
        Bounds3 b;
        bool volume = false, deforms = false;
        for (uint32_t mi : scene.objects[inst.object].meshes) {
            const TriangleMesh& mesh = scene.meshes[mi];
            volume |= has_volume(mesh.material);
            deforms |= !mesh.motion_positions.empty();
            for (const Vec3& q : mesh.positions) b.expand(inst.to_world.point(q));
        }
        if (!volume || deforms || b.empty()) continue;
        // A margin far beyond the hit points' rounding (1e-4 of the extent and of the
        // coordinates): only points clearly outside count.
        const Vec3 d = b.diagonal();
        const float extent = std::max({d.x, d.y, d.z, std::abs(b.lo.x), std::abs(b.lo.y),
                                       std::abs(b.lo.z), std::abs(b.hi.x), std::abs(b.hi.y),
                                       std::abs(b.hi.z)});
        const Vec3 margin(1e-4f * extent + 1e-6f);
        m_bounds[ii] = {b.lo - margin, b.hi + margin};
    }
}

}  // namespace penumbra
