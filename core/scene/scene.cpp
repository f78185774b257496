#include "core/scene/scene.h"

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

}  // namespace penumbra
