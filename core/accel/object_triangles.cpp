#include "core/accel/object_triangles.h"

#include "core/error.h"
#include "core/scene/motion.h"

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
    if (!deforms()) return;
    // Time steps move with their triangle, so a leaf's steps stay together too.
    std::vector<TriangleMotion> m(new_order.size());
    std::vector<Vec3> mv;
    mv.reserve(motion_verts.size());
    for (size_t i = 0; i < new_order.size(); ++i) {
        const TriangleMotion& old = motion[new_order[i]];
        m[i] = {static_cast<uint32_t>(mv.size()), old.steps};
        mv.insert(mv.end(), motion_verts.begin() + old.first,
                  motion_verts.begin() + old.first + 3 * old.steps);
    }
    motion = std::move(m);
    motion_verts = std::move(mv);
}

void ObjectTriangles::vertices_at(size_t i, float u, Vec3 p[3]) const {
    const TriangleMotion& m = motion[i];
    if (m.steps == 0) {
        for (int k = 0; k < 3; ++k) p[k] = verts[3 * i + k];
        return;
    }
    float f;
    const int s = time_segment(u, static_cast<int>(m.steps), &f);
    const Vec3* a = &motion_verts[m.first + 3 * s];
    for (int k = 0; k < 3; ++k) p[k] = lerp_step(a[k], a[k + 3], f);
}

ObjectTriangles gather_object_triangles(const Scene& scene, const Object& object) {
    ObjectTriangles out;
    size_t total = 0;
    for (uint32_t m : object.meshes) total += scene.meshes[m].triangle_count();
    bool deforms = false;
    for (uint32_t m : object.meshes) deforms |= !scene.meshes[m].motion_positions.empty();
    out.verts.reserve(3 * total);
    out.ids.reserve(total);
    if (deforms) out.motion.reserve(total);
    for (uint32_t m : object.meshes) {
        const TriangleMesh& mesh = scene.meshes[m];
        const size_t n = mesh.triangle_count();
        const auto& steps = mesh.motion_positions;
        for (size_t t = 0; t < n; ++t) {
            Vec3 p[3];
            bool finite = true;
            for (int k = 0; k < 3; ++k) {
                const uint32_t vi = mesh.indices[3 * t + k];
                CHECK(vi < mesh.positions.size(),
                      "mesh " << mesh.name << ": vertex index " << vi << " is out of range");
                p[k] = mesh.positions[vi];
                finite = finite && is_finite(p[k]);
                for (const auto& step : steps) finite = finite && is_finite(step[vi]);
            }
            // Embree drops a triangle with a non-finite vertex at any time step too.
            if (!finite) continue;
            for (int k = 0; k < 3; ++k) {
                out.verts.push_back(p[k]);
                out.bounds.expand(p[k]);
            }
            out.ids.push_back({m, static_cast<uint32_t>(t)});
            if (!deforms) continue;
            out.motion.push_back({static_cast<uint32_t>(out.motion_verts.size()),
                                  static_cast<uint32_t>(steps.size())});
            for (const auto& step : steps)
                for (int k = 0; k < 3; ++k) {
                    const Vec3 q = step[mesh.indices[3 * t + k]];
                    out.motion_verts.push_back(q);
                    out.bounds.expand(q);
                }
        }
    }
    return out;
}

}  // namespace penumbra
