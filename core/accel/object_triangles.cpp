#include "core/accel/object_triangles.h"

#include "core/error.h"

namespace penumbra {

void ObjectTriangles::reorder(const std::vector<uint32_t>& new_order) {
    std::vector<Vec3> v(3 * new_order.size());
    std::vector<TriangleId> id(new_order.size());
    for (size_t i = 0; i < new_order.size(); ++i) {
        const uint32_t j = new_order[i];
        for (int k = 0; k < 3; ++k) v[3 * i + k] = verts[3 * j + k];
        id[i] = ids[j];
    }
    verts = std::move(v);
    ids = std::move(id);
}

ObjectTriangles gather_object_triangles(const Scene& scene, const Object& object) {
    ObjectTriangles out;
    size_t total = 0;
    for (uint32_t m : object.meshes) total += scene.meshes[m].triangle_count();
    out.verts.reserve(3 * total);
    out.ids.reserve(total);
    for (uint32_t m : object.meshes) {
        const TriangleMesh& mesh = scene.meshes[m];
        const size_t n = mesh.triangle_count();
        for (size_t t = 0; t < n; ++t) {
            Vec3 p[3];
            bool finite = true;
            for (int k = 0; k < 3; ++k) {
                const uint32_t vi = mesh.indices[3 * t + k];
                CHECK(vi < mesh.positions.size(),
                      "mesh " << mesh.name << ": vertex index " << vi << " is out of range");
                p[k] = mesh.positions[vi];
                finite = finite && is_finite(p[k]);
            }
            if (!finite) continue;
            for (int k = 0; k < 3; ++k) {
                out.verts.push_back(p[k]);
                out.bounds.expand(p[k]);
            }
            out.ids.push_back({m, static_cast<uint32_t>(t)});
        }
    }
    return out;
}

}  // namespace penumbra
