#include "core/media/medium_set.h"

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
}

}  // namespace penumbra
