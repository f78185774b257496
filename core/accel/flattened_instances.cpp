#include "core/accel/flattened_instances.h"

namespace penumbra {

std::vector<bool> flattened_instances(const Scene& scene, const EmbreeBuildOptions& options) {
    std::vector<bool> flat(scene.instances.size(), false);
    if (!options.flatten) return flat;
    std::vector<size_t> placements(scene.objects.size(), 0);
    std::vector<bool> rigid(scene.objects.size(), true);
    for (const Instance& inst : scene.instances) {
        ++placements[inst.object];
        if (!inst.motion.empty()) rigid[inst.object] = false;
    }
    std::vector<bool> flat_object(scene.objects.size(), false);
    size_t budget = options.flatten_budget;
    for (size_t oi = 0; oi < scene.objects.size(); ++oi) {
        size_t triangles = 0;
        for (uint32_t mi : scene.objects[oi].meshes) {
            if (!scene.meshes[mi].motion_positions.empty()) rigid[oi] = false;
            triangles += scene.meshes[mi].triangle_count();
        }
        const size_t copies = triangles * placements[oi];
        if (rigid[oi] && placements[oi] > 0 && copies <= options.flatten_triangles &&
            copies <= budget) {
            flat_object[oi] = true;
            budget -= copies;
        }
    }
    for (size_t ii = 0; ii < scene.instances.size(); ++ii)
        flat[ii] = flat_object[scene.instances[ii].object];
    return flat;
}

}  // namespace penumbra
