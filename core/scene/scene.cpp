#include "core/scene/scene.h"

namespace penumbra {

Bounds3 Scene::bounds() const {
    Bounds3 b;
    for (const Instance& inst : instances) b.expand(inst.to_world.bounds(objects[inst.object].bounds));
    return b;
}

size_t Scene::triangle_count() const {
    size_t n = 0;
    for (const Instance& inst : instances)
        for (uint32_t m : objects[inst.object].meshes) n += meshes[m].triangle_count();
    return n;
}

const MaterialDesc& Scene::material(int index) const {
    static const MaterialDesc default_material;
    return index >= 0 ? materials[index] : default_material;
}

}  // namespace penumbra
