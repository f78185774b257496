// Which instances EmbreeAccel traces as world-space triangles of its top level
// (EmbreeBuildOptions::flatten): those of rigid objects whose every placement is static,
// small in all.
#pragma once

#include <vector>

#include "core/accel/embree_accel.h"
#include "core/scene/scene.h"

namespace penumbra {

// Per Scene instance: true where it is flattened. An object is flattened whole (every
// placement) when its triangles times its placements are at most flatten_triangles and
// the copies of the objects flattened before it, in object order, leave room within
// flatten_budget.
std::vector<bool> flattened_instances(const Scene& scene, const EmbreeBuildOptions& options);

}  // namespace penumbra
