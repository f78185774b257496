#include "core/scene/scene.h"

#include <algorithm>
#include <cmath>

#include "core/scene/motion.h"

namespace penumbra {

Bounds3 Scene::bounds() const {
    Bounds3 b;
    for (const Instance& inst : instances) {
        const Bounds3& ob = objects[inst.object].bounds;
        b.expand(inst.motion.empty() ? inst.to_world.bounds(ob)
                                     : motion_bounds(decompose_steps(inst.motion), ob));
    }
    return b;
}

bool Scene::has_motion() const { return scene_has_motion(*this); }

size_t Scene::triangle_count() const {
    size_t n = 0;
    for (const Instance& inst : instances)
        for (uint32_t m : objects[inst.object].meshes) n += meshes[m].triangle_count();
    return n;
}

const MaterialDesc& Scene::default_material() {
    static const MaterialDesc material;
    return material;
}

int Scene::timed_material(uint32_t instance, int material, float time) const {
    if (instance < instances.size() && !instances[instance].visibility.constant() &&
        !instances[instance].visibility.at(time))
        return hidden_material;
    if (material < 0 || size_t(material) >= material_steps.size()) return material;
    const std::vector<int>& steps = material_steps[size_t(material)];
    if (steps.empty()) return material;
    const float k = std::round(std::clamp(time, 0.0f, 1.0f) * float(steps.size() - 1));
    return steps[size_t(k)];
}

bool Scene::may_emit(int m) const {
    if (material(m).is_emissive()) return true;
    if (m < 0 || size_t(m) >= material_steps.size()) return false;
    for (int step : material_steps[size_t(m)])
        if (material(step).is_emissive()) return true;
    return false;
}

bool Scene::material_varies(uint32_t instance, int material) const {
    if (!timed_materials) return false;
    if (instance < instances.size() && !instances[instance].visibility.constant()) return true;
    return material >= 0 && size_t(material) < material_steps.size() &&
           !material_steps[size_t(material)].empty();
}

}  // namespace penumbra
