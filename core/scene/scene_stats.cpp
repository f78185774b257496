#include "core/scene/scene_stats.h"

namespace penumbra {

namespace {

template <typename T>
size_t bytes(const std::vector<T>& v) {
    return v.capacity() * sizeof(T);
}

}  // namespace

size_t mesh_memory_bytes(const TriangleMesh& m) {
    size_t n = bytes(m.positions) + bytes(m.normals) + bytes(m.uv0) + bytes(m.uv1) +
               bytes(m.tangents) + bytes(m.colors) + bytes(m.indices);
    for (const auto& p : m.motion_positions) n += bytes(p);
    for (const auto& p : m.motion_normals) n += bytes(p);
    return n;
}

size_t mesh_memory_bytes(const Scene& scene) {
    size_t n = 0;
    for (const TriangleMesh& m : scene.meshes) n += mesh_memory_bytes(m);
    return n;
}

size_t unique_triangle_count(const Scene& scene) {
    size_t n = 0;
    for (const TriangleMesh& m : scene.meshes) n += m.triangle_count();
    return n;
}

}  // namespace penumbra
