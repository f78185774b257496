// Where a ray meets a triangle that traversal has already chosen (Embree's hits): the
// distance to the triangle's plane and the barycentrics of the point there, from a plane
// record that can be precomputed where one triangle is hit many times.
#pragma once

#include <cmath>

#include "core/accel/triangle_intersect.h"
#include "core/math/float4.h"
#include "core/math/vec.h"
#include "core/ray.h"

namespace penumbra {

// A triangle as triangle_plane_hit reads it: vertex 0, the plane's normal n = e1 x e2,
// and the dual vectors g1 = (e2 x n) / |n|^2, g2 = (n x e1) / |n|^2, so that a point q on
// the plane has barycentrics b1 = (q - p0).g1, b2 = (q - p0).g2. 48 bytes, precomputed
// where one triangle is hit many times (EmbreeAccel's flattened meshes).
struct TrianglePlane {
    Vec3 p0, n, g1, g2;
};

inline TrianglePlane make_triangle_plane(Vec3 p0, Vec3 p1, Vec3 p2) {
    const Vec3 e1 = p1 - p0, e2 = p2 - p0;
    const Vec3 n = cross(e1, e2);
    const float inv_nn = 1.0f / dot(n, n);  // inf for a degenerate triangle: g is not finite
    return {p0, n, cross(e2, n) * inv_nn, cross(n, e1) * inv_nn};
}

// t and the barycentrics, whatever the hit point's side of the edges (within rounding of
// an edge they may be a little negative). t is the distance to the plane, n.(p0 - o) / n.d
// (intersect_triangle's formula). The barycentrics are those of the point o + t d on the
// plane: measured from the ray's origin instead (Moeller-Trumbore), a ray that grazes a
// face at 4e-4 radians from 10 units away put the point 1.4e-3 along the ray from where t
// says (float's 1e-7 relative, over the sine), which a volume's chord inherits. False
// where the ray is parallel to the plane in float, the triangle is degenerate, or the
// input is NaN.
//
// The arithmetic is that of the formulas on Vec3 (dot's (x + y) + z, no fused
// multiply-add), done two dot products at a time in F4 lanes: the same bits in two thirds
// of the scalar code's instructions, which matters because every hit EmbreeAccel reports
// comes through here (docs/performance-traversal.md, "Hits recomputed from Embree's choice of
// triangle").
inline bool triangle_plane_hit(const TrianglePlane& tp, const Ray& ray, TriangleHit* hit) {
    // Lanes 0-2 hold x, y, z; lane 3 holds the next member and is never summed. g2 is the
    // last member and is read as three floats.
    const F4 p0 = F4::loadu(&tp.p0.x), n = F4::loadu(&tp.n.x), g1 = F4::loadu(&tp.g1.x);
    const F4 g2 = F4::load3(tp.g2);
    // A Ray's o and d are followed by more of the Ray, so they too are read as four floats.
    const F4 fo = F4::loadu(&ray.o.x), fd = F4::loadu(&ray.d.x);
    const F4 s = sum3_pair(n * fd, n * (p0 - fo));  // n.d, n.(p0 - o)
    const float t = s.lane1() / s.lane0();
    const F4 q = (fo + fd * F4(t)) - p0;
    const F4 b = sum3_pair(q * g1, q * g2);  // q.g1, q.g2
    hit->t = t;
    hit->b1 = b.lane0();
    hit->b2 = b.lane1();
    // One test covers every failure: where n.d is 0 or NaN, or t overflows, t is not
    // finite, so neither is any component of q (inf or NaN), nor then either product
    // sum with g1 or g2 (each term inf or NaN).
    return std::isfinite(hit->b1) && std::isfinite(hit->b2);
}

}  // namespace penumbra
