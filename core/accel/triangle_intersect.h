// Watertight ray-triangle intersection (Woop, Benthin, Wald 2013, "Watertight
// Ray/Triangle Intersection", JCGT 2(1)): the ray is sheared and permuted so that it
// runs along +z from the origin, and the 2D edge functions decide; a ray cannot pass
// between two triangles that share an edge or a vertex.
#pragma once

#include <cmath>
#include <utility>

#include "core/math/vec.h"
#include "core/ray.h"

namespace penumbra {

// Per-ray shear constants (section 3 of the paper), computed once per ray.
struct TrianglePrecomp {
    Vec3 o, d;
    int kx = 0, ky = 1, kz = 2;
    float sx = 0, sy = 0, sz = 1;

    explicit TrianglePrecomp(const Ray& ray) : o(ray.o), d(ray.d) {
        const Vec3 a(std::abs(ray.d.x), std::abs(ray.d.y), std::abs(ray.d.z));
        // The dimension where |d| is largest becomes z; ties pick the first so the choice
        // is deterministic. NaN directions fall through to z and then miss below.
        kz = (a.x >= a.y && a.x >= a.z) ? 0 : (a.y >= a.z ? 1 : 2);
        kx = (kz + 1) % 3;
        ky = (kx + 1) % 3;
        // Swapping x and y when d.z < 0 keeps the winding, so the edge functions' signs
        // keep their meaning (the paper's "swap kx and ky").
        if (ray.d[kz] < 0) std::swap(kx, ky);
        sx = ray.d[kx] / ray.d[kz];
        sy = ray.d[ky] / ray.d[kz];
        sz = 1.0f / ray.d[kz];
    }
};

// b1, b2: barycentric weights of vertices 1 and 2 (Embree's u and v); t in units of |d|.
struct TriangleHit {
    float t, b1, b2;
};

// Hits with tmin <= t <= tmax count, as in Embree 3's robust mode, which EmbreeAccel uses
// (its Pluecker test checks tnear <= t <= tfar; the default Moeller test would exclude
// t = tnear: kernels/geometry/triangle_intersector_{pluecker,moeller}.h). The test is on
// the divided t, so the reported t itself obeys it. Both faces are hit (no culling).
// Returns false for degenerate (zero-area) triangles and NaN input.
inline bool intersect_triangle(const TrianglePrecomp& r, Vec3 p0, Vec3 p1, Vec3 p2, float tmin,
                               float tmax, TriangleHit* hit) {
    // Vertices relative to the ray origin, then sheared so the ray is the +z axis.
    const Vec3 A = p0 - r.o, B = p1 - r.o, C = p2 - r.o;
    const float ax = A[r.kx] - r.sx * A[r.kz], ay = A[r.ky] - r.sy * A[r.kz];
    const float bx = B[r.kx] - r.sx * B[r.kz], by = B[r.ky] - r.sy * B[r.kz];
    const float cx = C[r.kx] - r.sx * C[r.kz], cy = C[r.ky] - r.sy * C[r.kz];

    // Scaled barycentrics: U weighs vertex 0, V vertex 1, W vertex 2 (edge functions of
    // the edges opposite each vertex).
    float U = cx * by - cy * bx;
    float V = ax * cy - ay * cx;
    float W = bx * ay - by * ax;
    // An edge function that rounds to exactly 0 cannot be trusted to have the sign the
    // neighbouring triangle sees: redo all three in double, where the products of floats
    // are exact (section 4 of the paper).
    if (U == 0 || V == 0 || W == 0) {
        U = static_cast<float>(double(cx) * by - double(cy) * bx);
        V = static_cast<float>(double(ax) * cy - double(ay) * cx);
        W = static_cast<float>(double(bx) * ay - double(by) * ax);
    }
    // Inside when all three have the same sign (either winding); zeros are on the edge
    // and count. The negated comparisons also reject NaN.
    const bool any_neg = U < 0 || V < 0 || W < 0;
    const bool any_pos = U > 0 || V > 0 || W > 0;
    if (any_neg && any_pos) return false;
    const float det = U + V + W;
    if (det == 0 || std::isnan(det)) return false;

    // The paper's t interpolates the vertices' sheared z with the scaled barycentrics.
    // On slivers seen at a shallow angle det is tiny and the rounding of U, V, W is not,
    // so that t can be off by 1e-4 relative (measured on the chamfers of the Khronos
    // BoxAnimated model, cos = 0.06). The distance to the triangle's plane, as Embree
    // computes it, does not depend on the triangle's shape: use it, and the paper's t
    // only when the plane is parallel to the ray in float. Hit or miss is still decided
    // by the edge functions alone, so watertightness is unchanged.
    const float inv_det = 1.0f / det;
    const Vec3 n = cross(p1 - p0, p2 - p0);
    const float nd = dot(n, r.d);
    float t;
    if (nd != 0) {
        t = dot(n, A) / nd;
    } else {
        const float az = r.sz * A[r.kz], bz = r.sz * B[r.kz], cz = r.sz * C[r.kz];
        t = (U * az + V * bz + W * cz) * inv_det;
    }
    if (!(t >= tmin && t <= tmax)) return false;
    hit->t = t;
    hit->b1 = V * inv_det;
    hit->b2 = W * inv_det;
    return true;
}

}  // namespace penumbra
