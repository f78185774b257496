// The scene's media, built once before rendering: the interior medium of every material
// with KHR_materials_volume (thickness > 0). Materials are looked up by index.
#pragma once

#include <memory>
#include <vector>

#include "core/math/bounds.h"
#include "core/media/medium.h"
#include "core/scene/scene.h"

namespace penumbra {

class MediumSet {
public:
    MediumSet() = default;
    explicit MediumSet(const Scene& scene);

    // Whether material's meshes enclose a volume (a refracting boundary with a medium
    // inside) rather than thin-walled sheets. The glTF default material (-1) does not.
    bool has_volume(int material) const {
        return material >= 0 && material < int(m_media.size()) && m_media[material];
    }
    // The medium inside material's meshes; null when it has no volume. Clear volumes
    // (attenuationDistance infinite) have a medium too, whose is_clear() is true.
    const Medium* interior(int material) const {
        return has_volume(material) ? m_media[material].get() : nullptr;
    }
    // Whether any material has a volume: without one, paths never carry a medium.
    bool any() const {
        for (const auto& m : m_media)
            if (m) return true;
        return false;
    }

    // Whether p lies clearly outside the world bounds of instance (static instances
    // with a volume; false for others): a path there cannot be inside that instance's
    // closed meshes, whatever its stack says. Robust traversal reports hits within
    // rounding outside a triangle, so a ray skimming past a box's edge can "enter" a
    // face it passed by; without this the path would carry the medium until it escapes.
    bool surely_outside(int instance, Vec3 p) const {
        if (instance < 0 || instance >= int(m_bounds.size())) return false;
        const Bounds3& b = m_bounds[instance];
        return !b.empty() && (p.x < b.lo.x || p.y < b.lo.y || p.z < b.lo.z || p.x > b.hi.x ||
                              p.y > b.hi.y || p.z > b.hi.z);
    }

private:
    std::vector<std::shared_ptr<const Medium>> m_media;  // per material; null: thin-walled
    // Per instance: its world bounds grown by a margin where it holds a volume material
    // and neither moves nor deforms; empty otherwise (never "outside").
    std::vector<Bounds3> m_bounds;
};

// KHR_materials_volume's switch: thicknessFactor > 0 makes the mesh a closed volume; 0
// (the default, and any material without the extension) is thin-walled. The thickness
// value and texture are the raster approximation's and play no part in tracing.
bool material_has_volume(const MaterialDesc& m);

}  // namespace penumbra
