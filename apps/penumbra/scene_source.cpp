#include "apps/penumbra/scene_source.h"

#include <cstring>

#include "apps/penumbra/scene_setup.h"

namespace penumbra {

namespace {

bool same_bits(const Transform& a, const Transform& b) {
    return std::memcmp(&a.matrix(), &b.matrix(), sizeof(Mat4)) == 0;
}

// What an accelerator reads of the instances: which object each places, and where.
bool same_placements(const std::vector<Instance>& a, const std::vector<Instance>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        if (a[i].object != b[i].object || !same_bits(a[i].to_world, b[i].to_world) ||
            a[i].motion.size() != b[i].motion.size())
            return false;
        for (size_t k = 0; k < a[i].motion.size(); ++k)
            if (!same_bits(a[i].motion[k], b[i].motion[k])) return false;
    }
    return true;
}

}  // namespace

void SceneSource::recycle(std::unique_ptr<SceneSetup> setup) {
    if (!setup) return;
    // What refers to the scene goes first.
    setup->camera.reset();
    setup->lights.reset();
    m_accel.reset();
    if (asset && asset->keeps_geometry(setup->scene)) {
        m_accel = std::move(setup->accel);
        m_instances = std::move(setup->scene.instances);
        m_static_builds = asset->static_builds();
    }
    setup->accel.reset();
    Scene scene = std::move(setup->scene);
    setup.reset();
    if (asset) asset->recycle(std::move(scene));
}

std::unique_ptr<Accel> SceneSource::reuse_accel(const Scene& scene) {
    std::unique_ptr<Accel> accel = std::move(m_accel);
    const bool fits = accel && asset && asset->static_builds() == m_static_builds &&
                      asset->keeps_geometry(scene) && same_placements(m_instances, scene.instances);
    m_instances.clear();
    if (!fits) return nullptr;
    accel->rebind(scene);
    return accel;
}

}  // namespace penumbra
