#include "core/surface_point.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/facet.h"
#include "core/math/float4.h"
#include "core/scene/motion.h"

namespace penumbra {

namespace {

constexpr float gamma(int n) { return rounding_gamma(n); }

Vec3 abs(Vec3 v) { return {std::abs(v.x), std::abs(v.y), std::abs(v.z)}; }

// Error of xf.point(q) when q carries q_err (pbrt-v4, section 6.8.6).
[[gnu::always_inline]] inline Vec3 point_error(const Transform& xf, Vec3 q, Vec3 q_err) {
    const Mat4& m = xf.matrix();
    float e[3];
    if (xf.is_translation_only()) {
        // The general sums below with their exact 0 and 1 terms dropped: the same values.
        for (int r = 0; r < 3; ++r)
            e[r] = (gamma(3) + 1) * q_err[r] + gamma(3) * (std::abs(q[r]) + std::abs(m(r, 3)));
        return {e[0], e[1], e[2]};
    }
    for (int r = 0; r < 3; ++r) {
        const float carried =
            std::abs(m(r, 0)) * q_err.x + std::abs(m(r, 1)) * q_err.y + std::abs(m(r, 2)) * q_err.z;
        const float made = std::abs(m(r, 0) * q.x) + std::abs(m(r, 1) * q.y) +
                           std::abs(m(r, 2) * q.z) + std::abs(m(r, 3));
        e[r] = (gamma(3) + 1) * carried + gamma(3) * made;
    }
    return {e[0], e[1], e[2]};
}

// The cone's width over |cos| (the footprint's long axis on the surface) times each UV
// set's ratio sqrt(uv area / world area) of the triangle: the paper's Delta_0 = 0.5
// log2(t_a / p_a), in UV units rather than texels, so that one value serves textures of
// every size. 0 for a set the mesh lacks or a degenerate triangle.
void set_uv_widths(const TriangleMesh& mesh, const Transform& xf, const Ray& ray, Vec3 ng,
                   const uint32_t idx[3], Vec3 e1, Vec3 e2, float cone_width, float dlen,
                   float uv_width[2]) {
    uv_width[0] = uv_width[1] = 0;
    if (mesh.uv0.empty() && mesh.uv1.empty()) return;  // no UV set to give a width in
    const float world_area2 = length(cross(xf.vector(e1), xf.vector(e2)));
    if (!(world_area2 > 0) || !(dlen > 0)) return;
    const float cos = std::max(std::abs(dot(ng, ray.d)) / dlen, 1e-4f);
    const float w = cone_width / cos;
    const std::vector<Vec2>* sets[2] = {&mesh.uv0, &mesh.uv1};
    for (int s = 0; s < 2; ++s) {
        const std::vector<Vec2>& uv = *sets[s];
        if (uv.empty()) continue;
        const Vec2 d1 = uv[idx[1]] - uv[idx[0]], d2 = uv[idx[2]] - uv[idx[0]];
        const float uv_area2 = std::abs(d1.x * d2.y - d1.y * d2.x);
        uv_width[s] = w * std::sqrt(uv_area2 / world_area2);
    }
}

// The hit's place on the triangle: its vertices (where the general path reads them),
// the barycentric point q on the mesh, and the point p in the world with its error bound.
struct TrianglePoint {
    Vec3 p0, p1, p2, q, p, p_error;
};

// Interpolating the vertices is more accurate than o + t d far from the origin. The
// surface is where it was at the ray's time (motion.h: the static data when the mesh
// does not deform).
template <bool kBare>
[[gnu::always_inline]] inline void locate_hit(const TriangleMesh& mesh, const Transform& xf,
                                              const Ray& ray, const uint32_t idx[3], float b0,
                                              float b1, float b2, TrianglePoint& t) {
    const uint32_t i0 = idx[0], i1 = idx[1], i2 = idx[2];
    if (kBare && xf.is_affine()) {
        // The general lines below for a facet, in SSE lanes: the same operations in the
        // same order, so the same bits, in about 40 instructions fewer on a translated
        // instance (most bare facets' instances are translations, every identity one)
        // and 30 on any other (the point's rows and point_error's as columns times q's
        // coordinates; point() divides by no w for an affine matrix).
        const F4 a0 = F4::load3(mesh.positions[i0]) * F4(b0),
                 a1 = F4::load3(mesh.positions[i1]) * F4(b1),
                 a2 = F4::load3(mesh.positions[i2]) * F4(b2);
        const F4 q4 = a0 + a1 + a2;
        const F4 q_err = (abs4(a0) + abs4(a1) + abs4(a2)) * F4(gamma(7));
        if (xf.is_translation_only()) {
            const F4 c3 = F4::load(xf.column(3));
            t.p = (q4 + c3).xyz();
            t.p_error = (F4(gamma(3) + 1) * q_err + F4(gamma(3)) * (abs4(q4) + abs4(c3))).xyz();
            return;
        }
        const F4 c0 = F4::load(xf.column(0)), c1 = F4::load(xf.column(1)),
                 c2 = F4::load(xf.column(2)), c3 = F4::load(xf.column(3));
        const F4 x = c0 * q4.broadcast<0>(), y = c1 * q4.broadcast<1>(), z = c2 * q4.broadcast<2>();
        t.p = (x + y + z + c3).xyz();
        const F4 carried = abs4(c0) * q_err.broadcast<0>() + abs4(c1) * q_err.broadcast<1>() +
                           abs4(c2) * q_err.broadcast<2>();
        const F4 made = abs4(x) + abs4(y) + abs4(z) + abs4(c3);
        t.p_error = (F4(gamma(3) + 1) * carried + F4(gamma(3)) * made).xyz();
        return;
    }
    const bool deforms = !kBare && !mesh.motion_positions.empty();  // a facet: static
    t.p0 = deforms ? position_at(mesh, i0, ray.time) : mesh.positions[i0];
    t.p1 = deforms ? position_at(mesh, i1, ray.time) : mesh.positions[i1];
    t.p2 = deforms ? position_at(mesh, i2, ray.time) : mesh.positions[i2];
    t.q = t.p0 * b0 + t.p1 * b1 + t.p2 * b2;
    t.p = xf.point(t.q);
    t.p_error = point_error(xf, t.q, (abs(t.p0 * b0) + abs(t.p1 * b1) + abs(t.p2 * b2)) * gamma(7));
}

// The shading normal (and the smooth surface's point, p_smooth) from the vertex normals,
// where the mesh has them and the facet is not flat; else ns and p_smooth stay as given
// (ng and p), or ns turns to n0's side of a flat facet. face: the unnormalized face
// normal, computed where the hit has no facet.
template <bool kBare>
[[gnu::always_inline]] inline void shading_normal(const TriangleMesh& mesh, const Transform& xf,
                                                  const Ray& ray, const uint32_t idx[3],
                                                  const float b[3], const Facet* facet,
                                                  const TrianglePoint& t, const Vec3& face, Vec3 ng,
                                                  bool has_ng, Vec3& ns, Vec3& p_smooth) {
    if (kBare || (facet && has_ng && (facet->flags & Facet::kFlat))) {
        // A flat facet's shading normal is ng on n0's side (is_flat_facet): no vertex
        // normal to read, transform and normalize at each hit. (A bare facet without
        // normals is never kOpposed: ns is ng.)
        if (facet->flags & Facet::kOpposed) ns = -ng;
        return;
    }
    if (mesh.normals.empty()) return;
    const bool bends = !mesh.motion_normals.empty();
    auto normal = [&](uint32_t i) {
        return bends ? normal_at(mesh, i, ray.time) : mesh.normals[i];
    };
    const Vec3 n0 = normal(idx[0]);
    Vec3 n1, n2;
    bool flat;
    if (facet) {  // only a flat facet's n1 and n2 go unread
        flat = (facet->flags & Facet::kFlat) != 0;
        if (!flat) {
            n1 = normal(idx[1]);
            n2 = normal(idx[2]);
        }
    } else {
        n1 = normal(idx[1]);
        n2 = normal(idx[2]);
        flat = is_flat_facet(n0, n1, n2, face);
    }
    if (flat && has_ng) {
        // The facet table's rule above, for hits without the table.
        if (dot(n0, face) < 0) ns = -ng;
        return;
    }
    Vec3 n = n0;
    if (!flat) {
        const Vec3 v[3] = {t.p0, t.p1, t.p2}, vn[3] = {n0, n1, n2};
        p_smooth = xf.point(smooth_surface_point(t.q, v, vn, b));
        n = n0 * b[0] + n1 * b[1] + n2 * b[2];
    }
    const Vec3 nw = xf.normal(n);
    const float len = length(nw);
    if (len > 0 && std::isfinite(len)) ns = nw / len;
}

// The interpolated vertex attributes a general hit reads: the UV sets, dp/du from the
// first one's parameterization (for tangent frames), the tangent and the colour.
struct HitAttributes {
    Vec2 uv0, uv1;
    Vec3 dpdu;
    Vec4 tangent;
    Vec4 color{1, 1, 1, 1};
};

[[gnu::always_inline]] inline void interpolate_attributes(const TriangleMesh& mesh,
                                                          const Transform& xf,
                                                          const uint32_t idx[3], const float b[3],
                                                          const TrianglePoint& t,
                                                          HitAttributes& a) {
    const uint32_t i0 = idx[0], i1 = idx[1], i2 = idx[2];
    if (!mesh.uv0.empty()) {
        const Vec2 t0 = mesh.uv0[i0], t1 = mesh.uv0[i1], t2 = mesh.uv0[i2];
        a.uv0 = t0 * b[0] + t1 * b[1] + t2 * b[2];
        const Vec2 d1 = t1 - t0, d2 = t2 - t0;
        const float det = d1.x * d2.y - d1.y * d2.x;
        if (std::abs(det) > 1e-20f)
            a.dpdu = xf.vector(((t.p1 - t.p0) * d2.y - (t.p2 - t.p0) * d1.y) / det);
    }
    if (!mesh.uv1.empty()) a.uv1 = mesh.uv1[i0] * b[0] + mesh.uv1[i1] * b[1] + mesh.uv1[i2] * b[2];
    if (!mesh.tangents.empty()) {
        const Vec4 tg =
            mesh.tangents[i0] * b[0] + mesh.tangents[i1] * b[1] + mesh.tangents[i2] * b[2];
        a.tangent = Vec4(xf.vector(tg.xyz()), mesh.tangents[i0].w < 0 ? -1.0f : 1.0f);
        if (xf.swaps_handedness()) a.tangent.w = -a.tangent.w;
    }
    if (!mesh.colors.empty())
        a.color = mesh.colors[i0] * b[0] + mesh.colors[i1] * b[1] + mesh.colors[i2] * b[2];
}

// The surface point on the mesh placed by xf (the instance's static transform, or its
// motion's at the ray's time: a separate argument, so that a static instance's is read in
// place, with no copy of the transform and its inverse). Every field is computed into a
// local and the record built once at the end: a SurfacePoint declared first would be
// zero-filled (its default member initializers, a `rep stos` of 120 bytes per hit) and
// then overwritten.
// kBare: the hit's facet has Facet::kBare, and every branch on what the mesh lacks is
// decided at compile time (the same arithmetic, so the same bits).
template <bool kBare>
[[gnu::always_inline]] inline SurfacePoint surface_point_on(const TriangleMesh& mesh,
                                                            const Transform& xf, const Ray& ray,
                                                            const Hit& hit) {
    const uint32_t idx[3] = {mesh.indices[3 * size_t(hit.prim)],
                             mesh.indices[3 * size_t(hit.prim) + 1],
                             mesh.indices[3 * size_t(hit.prim) + 2]};
    const float b1 = hit.b1, b2 = hit.b2, b0 = 1 - b1 - b2;
    const float b[3] = {b0, b1, b2};
    TrianglePoint t;
    locate_hit<kBare>(mesh, xf, ray, idx, b0, b1, b2, t);
    // The geometric normal and the flat-facet test (facet.h), from the hit's precomputed
    // facet where the accelerator has one, else here with the same functions.
    const Facet* facet = hit.facet;
    Vec3 face, ng;
    bool has_ng;
    if (kBare || facet) {
        has_ng = kBare || (facet->flags & Facet::kNormal) != 0;
        ng = facet->ng;
    } else {
        face = cross(t.p1 - t.p0, t.p2 - t.p0);
        has_ng = world_face_normal(xf, face, &ng);
    }
    if (!has_ng) ng = -normalize(ray.d);  // a degenerate triangle: face the ray
    Vec3 ns = ng, p_smooth = t.p;
    shading_normal<kBare>(mesh, xf, ray, idx, b, facet, t, face, ng, has_ng, ns, p_smooth);
    // The winding defines ng, but files are not always consistent with their normals:
    // trust the shading normals for which side is "outside".
    // (A bare facet's ns is +-ng, unit: the dot is +-1, and the flag says which.)
    const bool ng_is_front = kBare ? !(facet->flags & Facet::kOpposed) : !(dot(ng, ns) < 0);
    if (!ng_is_front) ng = -ng;
    HitAttributes a;
    if (!kBare) interpolate_attributes(mesh, xf, idx, b, t, a);
    float cone_width = 0, uv_width[2] = {0, 0};
    if (ray.cone.active()) {
        const float dlen = length(ray.d);
        cone_width = ray.cone.width_at(hit.t * dlen);
        if (!kBare)  // no UV set to give a width in
            set_uv_widths(mesh, xf, ray, ng, idx, t.p1 - t.p0, t.p2 - t.p0, cone_width, dlen,
                          uv_width);
    }
    return SurfacePoint{
        t.p,     p_smooth,  t.p_error,    ng,       ng_is_front, ns,
        a.dpdu,  a.tangent, a.uv0,        a.uv1,    cone_width,  {uv_width[0], uv_width[1]},
        a.color, hit.t,     hit.instance, hit.mesh, hit.prim,    mesh.material};
}

// A moving instance's hit, with its transform at the ray's time; out of line, so that
// the static case above inlines surface_point_on once and reads its transform in place
// (an optional holding the moving one cost about 20 instructions a hit).
[[gnu::noinline]] SurfacePoint moving_surface_point(const TriangleMesh& mesh, const Instance& inst,
                                                    const Ray& ray, const Hit& hit) {
    return surface_point_on<false>(mesh, instance_transform_at(inst, ray.time), ray, hit);
}

// Any other hit on a static instance; out of line, so that make_surface_point keeps the
// bare path's few registers and small frame (the general path spills a 0x228-byte one).
[[gnu::noinline]] SurfacePoint static_surface_point(const TriangleMesh& mesh, const Transform& xf,
                                                    const Ray& ray, const Hit& hit) {
    return surface_point_on<false>(mesh, xf, ray, hit);
}

// The hit's point with its mesh's material.
[[gnu::always_inline]] inline SurfacePoint placed_surface_point(const Scene& scene,
                                                               const Ray& ray, const Hit& hit) {
    const Instance& inst = scene.instances[hit.instance];
    const TriangleMesh& mesh = scene.meshes[hit.mesh];
    if (!inst.motion.empty()) return moving_surface_point(mesh, inst, ray, hit);
    if (hit.facet && (hit.facet->flags & Facet::kBare))
        return surface_point_on<true>(mesh, inst.to_world, ray, hit);
    return static_surface_point(mesh, inst.to_world, ray, hit);
}

}  // namespace

SurfacePoint make_surface_point(const Scene& scene, const Ray& ray, const Hit& hit) {
    SurfacePoint sp = placed_surface_point(scene, ray, hit);
    // Animated materials and instances hidden for part of the shutter: the material at
    // the ray's time.
    if (scene.timed_materials) sp.material = scene.timed_material(hit.instance, sp.material, ray.time);
    return sp;
}

Vec3 smooth_surface_point(Vec3 p, const Vec3 v[3], const Vec3 n[3], const float b[3]) {
    Vec3 lifted = p;
    for (int i = 0; i < 3; ++i) {
        const float len2 = dot(n[i], n[i]);
        if (!(len2 > 0) || !std::isfinite(len2)) continue;
        // Signed height of p over vertex i's tangent plane, times |n|^2.
        const float h = std::min(0.0f, dot(p - v[i], n[i]));
        lifted -= n[i] * (b[i] * h / len2);
    }
    return lifted;
}

Vec3 offset_ray_origin(Vec3 p, Vec3 ng, Vec3 w) {
    // A relative offset (a few float ULPs of the largest coordinate) plus an absolute
    // floor for points near the origin.
    const float scale = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), 1e-2f});
    const float eps = 32.0f * std::numeric_limits<float>::epsilon() * scale;
    return p + (dot(w, ng) < 0 ? -ng : ng) * eps;
}

}  // namespace penumbra
