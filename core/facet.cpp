#include "core/facet.h"

namespace penumbra {

Facet make_facet(const TriangleMesh& mesh, const Transform& xf, uint32_t prim) {
    const uint32_t i0 = mesh.indices[3 * size_t(prim)], i1 = mesh.indices[3 * size_t(prim) + 1],
                   i2 = mesh.indices[3 * size_t(prim) + 2];
    const Vec3 p0 = mesh.positions[i0];
    const Vec3 face = cross(mesh.positions[i1] - p0, mesh.positions[i2] - p0);
    Facet f;
    if (world_face_normal(xf, face, &f.ng)) f.flags |= Facet::kNormal;
    if (!mesh.normals.empty() &&
        is_flat_facet(mesh.normals[i0], mesh.normals[i1], mesh.normals[i2], face)) {
        f.flags |= Facet::kFlat;
        if (dot(mesh.normals[i0], face) < 0) f.flags |= Facet::kOpposed;
    }
    const bool shading_is_ng = mesh.normals.empty() || (f.flags & Facet::kFlat);
    if ((f.flags & Facet::kNormal) && shading_is_ng && mesh.uv0.empty() && mesh.uv1.empty() &&
        mesh.tangents.empty() && mesh.colors.empty())
        f.flags |= Facet::kBare;
    return f;
}

std::vector<Facet> make_facets(const TriangleMesh& mesh, const Transform& xf) {
    std::vector<Facet> facets;
    if (!mesh.motion_positions.empty() || !mesh.motion_normals.empty()) return facets;
    const auto n = static_cast<uint32_t>(mesh.triangle_count());
    facets.reserve(n);
    for (uint32_t prim = 0; prim < n; ++prim) facets.push_back(make_facet(mesh, xf, prim));
    return facets;
}

}  // namespace penumbra
