// Sizes of a Scene's mesh data, for memory figures (docs/performance.md, "Big scenes") and
// for tests that check that loading holds each array once.
#pragma once

#include <cstddef>

#include "core/scene/scene.h"

namespace penumbra {

// Heap bytes of a mesh's vertex and index arrays, by capacity (what they hold, used or not).
size_t mesh_memory_bytes(const TriangleMesh& mesh);
// The same over all of Scene::meshes (each mesh once, however many instances place it).
size_t mesh_memory_bytes(const Scene& scene);
// Triangles of Scene::meshes, each mesh once (Scene::triangle_count counts per instance).
size_t unique_triangle_count(const Scene& scene);

}  // namespace penumbra
