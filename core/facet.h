// Per-triangle values that make_surface_point would otherwise recompute at every hit on a
// static triangle under a static transform: the world geometric normal and whether the
// facet is flat-shaded. An accelerator may build them once and point each Hit at its
// triangle's (Hit::facet); they are the per-hit values bit for bit (the same functions).
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "core/math/transform.h"
#include "core/math/vec.h"
#include "core/scene/scene.h"

namespace penumbra {

// 16 bytes per triangle and placement.
struct Facet {
    Vec3 ng;             // world_face_normal's unit normal (valid when kNormal is set)
    uint32_t flags = 0;  // kNormal | kFlat | kOpposed | kBare

    // The triangle has a geometric normal (not degenerate): ng holds it. Without it the
    // hit takes the ray's reversed direction, which no table can hold.
    static constexpr uint32_t kNormal = 1;
    // The mesh has shading normals and they are flat over this triangle (is_flat_facet).
    static constexpr uint32_t kFlat = 2;
    // Flat, with the vertex normal against the face normal (a winding the file's normals
    // contradict): the shading normal is -ng.
    static constexpr uint32_t kOpposed = 4;
    // The hit needs nothing of the mesh but its positions: it has a normal, its shading
    // normal is +-ng (flat, or the mesh has no normals), and the mesh has no UVs, tangents
    // or colours. make_surface_point takes a path for these that reads and writes only
    // that: the common facet of untextured scenes (a Cornell box's walls).
    static constexpr uint32_t kBare = 8;
};
static_assert(sizeof(Facet) == 16, "the table's cost per triangle is stated as 16 bytes");

// The unit world normal of the object-space face normal `face` (cross(p1 - p0, p2 - p0))
// under xf; false for a degenerate triangle (a zero or NaN length). Normals transform with
// the inverse transpose: right under non-uniform scale, and under mirroring it keeps the
// normal on the side the (flipped) winding implies.
inline bool world_face_normal(const Transform& xf, Vec3 face, Vec3* ng) {
    const Vec3 n = xf.normal(face);
    const float len = length(n);
    if (!(len > 0)) return false;
    *ng = n / len;
    return true;
}

// A flat-shaded facet (three equal normals along the face normal, as glTF exporters write
// hard edges) has every vertex plane through its own plane: Hanika's lift would only add
// rounding noise, and the interpolation gives n0 back. Its shading normal is taken to be
// the geometric one (on n0's side), which it is to within 1e-6 radians.
inline bool is_flat_facet(Vec3 n0, Vec3 n1, Vec3 n2, Vec3 face) {
    const float norms2 = length_squared(n0) * length_squared(face);
    return n0 == n1 && n0 == n2 && std::isfinite(norms2) &&
           length_squared(cross(n0, face)) <= 1e-12f * norms2;
}

// The facet of triangle prim of mesh placed by xf. The mesh must not deform (no
// motion_positions or motion_normals): its facets would change within the shutter.
Facet make_facet(const TriangleMesh& mesh, const Transform& xf, uint32_t prim);

// Every triangle's facet, in index order; empty for a mesh that deforms.
std::vector<Facet> make_facets(const TriangleMesh& mesh, const Transform& xf);

}  // namespace penumbra
