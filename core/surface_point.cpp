#include "core/surface_point.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "core/math/next_float.h"
#include "core/scene/motion.h"

namespace penumbra {

namespace {

// Bounds on float rounding (pbrt-v4, section 6.8.1): n operations, unit roundoff u.
constexpr float gamma(int n) {
    constexpr float u = std::numeric_limits<float>::epsilon() * 0.5f;
    return n * u / (1 - n * u);
}

Vec3 abs(Vec3 v) { return {std::abs(v.x), std::abs(v.y), std::abs(v.z)}; }

// Error of xf.point(q) when q carries q_err (pbrt-v4, section 6.8.6).
Vec3 point_error(const Transform& xf, Vec3 q, Vec3 q_err) {
    const Mat4& m = xf.matrix();
    float e[3];
    if (xf.is_translation_only()) {
        // The general sums below with their exact 0 and 1 terms dropped: the same values.
        for (int r = 0; r < 3; ++r)
            e[r] = (gamma(3) + 1) * q_err[r] + gamma(3) * (std::abs(q[r]) + std::abs(m(r, 3)));
        return {e[0], e[1], e[2]};
    }
    for (int r = 0; r < 3; ++r) {
        const float carried = std::abs(m(r, 0)) * q_err.x + std::abs(m(r, 1)) * q_err.y +
                              std::abs(m(r, 2)) * q_err.z;
        const float made = std::abs(m(r, 0) * q.x) + std::abs(m(r, 1) * q.y) +
                           std::abs(m(r, 2) * q.z) + std::abs(m(r, 3));
        e[r] = (gamma(3) + 1) * carried + gamma(3) * made;
    }
    return {e[0], e[1], e[2]};
}

// The cone's width at the hit over |cos| (the footprint's long axis on the surface)
// times each UV set's ratio sqrt(uv area / world area) of the triangle: the paper's
// Delta_0 = 0.5 log2(t_a / p_a), in UV units rather than texels, so that one value
// serves textures of every size.
void set_texture_footprint(const TriangleMesh& mesh, const Transform& xf, const Ray& ray,
                           Vec3 e1, Vec3 e2, SurfacePoint& sp) {
    const float dlen = length(ray.d);
    sp.cone_width = ray.cone.width_at(sp.t * dlen);
    if (mesh.uv0.empty() && mesh.uv1.empty()) return;  // no UV set to give a width in
    const float world_area2 = length(cross(xf.vector(e1), xf.vector(e2)));
    if (!(world_area2 > 0) || !(dlen > 0)) return;
    const float cos = std::max(std::abs(dot(sp.ng, ray.d)) / dlen, 1e-4f);
    const float w = sp.cone_width / cos;
    const uint32_t* idx = &mesh.indices[3 * size_t(sp.prim)];
    const std::vector<Vec2>* sets[2] = {&mesh.uv0, &mesh.uv1};
    for (int s = 0; s < 2; ++s) {
        const std::vector<Vec2>& uv = *sets[s];
        if (uv.empty()) continue;
        const Vec2 d1 = uv[idx[1]] - uv[idx[0]], d2 = uv[idx[2]] - uv[idx[0]];
        const float uv_area2 = std::abs(d1.x * d2.y - d1.y * d2.x);
        sp.uv_width[s] = w * std::sqrt(uv_area2 / world_area2);
    }
}

}  // namespace

SurfacePoint make_surface_point(const Scene& scene, const Ray& ray, const Hit& hit) {
    const Instance& inst = scene.instances[hit.instance];
    const TriangleMesh& mesh = scene.meshes[hit.mesh];
    const uint32_t i0 = mesh.indices[3 * hit.prim], i1 = mesh.indices[3 * hit.prim + 1],
                   i2 = mesh.indices[3 * hit.prim + 2];
    const float b1 = hit.b1, b2 = hit.b2, b0 = 1 - b1 - b2;

    SurfacePoint sp;
    sp.t = hit.t;
    sp.instance = hit.instance;
    sp.mesh = hit.mesh;
    sp.prim = hit.prim;
    sp.material = mesh.material;

    // The surface where it was at the ray's time (motion.h: the static data when the
    // instance or mesh does not move).
    // Static instances and meshes (the common case) are read in place: no copy of the
    // transform and its inverse, no calls per vertex.
    std::optional<Transform> moving;
    if (!inst.motion.empty()) moving = instance_transform_at(inst, ray.time);
    const Transform& xf = moving ? *moving : inst.to_world;
    const bool deforms = !mesh.motion_positions.empty();
    const Vec3 p0 = deforms ? position_at(mesh, i0, ray.time) : mesh.positions[i0],
               p1 = deforms ? position_at(mesh, i1, ray.time) : mesh.positions[i1],
               p2 = deforms ? position_at(mesh, i2, ray.time) : mesh.positions[i2];
    // Interpolating the vertices is more accurate than o + t d far from the origin.
    const Vec3 q = p0 * b0 + p1 * b1 + p2 * b2;
    sp.p = xf.point(q);
    sp.p_error = point_error(xf, q, (abs(p0 * b0) + abs(p1 * b1) + abs(p2 * b2)) * gamma(7));
    const Vec3 e1 = p1 - p0, e2 = p2 - p0;
    // Normals transform with the inverse transpose: right under non-uniform scale, and
    // under mirroring it keeps the normal on the side the (flipped) winding implies.
    const Vec3 face = cross(e1, e2);
    Vec3 ng = xf.normal(face);
    const float ng_len = length(ng);
    ng = ng_len > 0 ? ng / ng_len : -normalize(ray.d);
    sp.ng = ng;

    Vec3 ns = ng;
    sp.p_smooth = sp.p;
    if (!mesh.normals.empty()) {
        const bool bends = !mesh.motion_normals.empty();
        const Vec3 n0 = bends ? normal_at(mesh, i0, ray.time) : mesh.normals[i0],
                   n1 = bends ? normal_at(mesh, i1, ray.time) : mesh.normals[i1],
                   n2 = bends ? normal_at(mesh, i2, ray.time) : mesh.normals[i2];
        // A flat-shaded facet (three equal normals along the face normal, as glTF
        // exporters write hard edges) has every vertex plane through its own plane:
        // the lift would only add rounding noise, and the interpolation gives n0 back.
        const float norms2 = length_squared(n0) * length_squared(face);
        const bool flat = n0 == n1 && n0 == n2 && std::isfinite(norms2) &&
                          length_squared(cross(n0, face)) <= 1e-12f * norms2;
        Vec3 n = n0;
        if (!flat) {
            const Vec3 v[3] = {p0, p1, p2}, vn[3] = {n0, n1, n2};
            const float b[3] = {b0, b1, b2};
            sp.p_smooth = xf.point(smooth_surface_point(q, v, vn, b));
            n = n0 * b0 + n1 * b1 + n2 * b2;
        }
        const Vec3 nw = xf.normal(n);
        const float len = length(nw);
        if (len > 0 && std::isfinite(len)) ns = nw / len;
    }
    sp.ns = ns;
    // The winding defines ng, but files are not always consistent with their normals:
    // trust the shading normals for which side is "outside".
    if (dot(sp.ng, sp.ns) < 0) {
        sp.ng = -sp.ng;
        sp.ng_is_front = false;
    }

    if (!mesh.uv0.empty()) {
        const Vec2 t0 = mesh.uv0[i0], t1 = mesh.uv0[i1], t2 = mesh.uv0[i2];
        sp.uv0 = t0 * b0 + t1 * b1 + t2 * b2;
        // dp/du from the triangle's UV parameterization (for tangent frames).
        const Vec2 d1 = t1 - t0, d2 = t2 - t0;
        const float det = d1.x * d2.y - d1.y * d2.x;
        if (std::abs(det) > 1e-20f) sp.dpdu = xf.vector((e1 * d2.y - e2 * d1.y) / det);
    }
    if (!mesh.uv1.empty())
        sp.uv1 = mesh.uv1[i0] * b0 + mesh.uv1[i1] * b1 + mesh.uv1[i2] * b2;
    if (!mesh.tangents.empty()) {
        const Vec4 t = mesh.tangents[i0] * b0 + mesh.tangents[i1] * b1 + mesh.tangents[i2] * b2;
        sp.tangent = Vec4(xf.vector(t.xyz()), mesh.tangents[i0].w < 0 ? -1.0f : 1.0f);
        if (xf.swaps_handedness()) sp.tangent.w = -sp.tangent.w;
    }
    if (!mesh.colors.empty())
        sp.color = mesh.colors[i0] * b0 + mesh.colors[i1] * b1 + mesh.colors[i2] * b2;
    if (ray.cone.active()) set_texture_footprint(mesh, xf, ray, e1, e2, sp);
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
    // floor for points near the origin. Issue "numerical robustness" refines this.
    const float scale = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), 1e-2f});
    const float eps = 32.0f * std::numeric_limits<float>::epsilon() * scale;
    return p + (dot(w, ng) < 0 ? -ng : ng) * eps;
}

Vec3 offset_ray_origin(Vec3 p, Vec3 p_error, Vec3 n, Vec3 w) {
    // Safety factor 4: the accelerators move the origin into instance space, which
    // rounds about as much again as p_error covers. The error bound is 0 along an axis
    // where every term is 0 (a plane y = 0), but the accelerators' arithmetic is not
    // exact: never less than gamma(3) of the largest coordinate (about 1.5 ULPs), nor a
    // tiny absolute floor.
    const float scale = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    const float d = 4 * std::max({dot(abs(n), p_error), gamma(3) * scale, 1e-20f});
    const Vec3 side = dot(w, n) < 0 ? -n : n;
    Vec3 po = p + side * d;
    // The addition rounds too: step each coordinate one float further along the normal.
    for (int i = 0; i < 3; ++i) {
        if (side[i] > 0) po[i] = next_float_up(po[i]);
        else if (side[i] < 0) po[i] = next_float_down(po[i]);
    }
    return po;
}

Ray spawn_ray(const SurfacePoint& sp, Vec3 w, float dist, float time) {
    Ray r;
    // The side a ray leaves on is decided by the interpolated normal sp.ns (as the file
    // gives it, with sp.ng turned to its side), as the integrators' side tests are: a
    // ray the facet's plane puts on the other side then starts above the facet and is
    // stopped by it unless the lifted origin clears the facet (a convex coarse mesh),
    // so it cannot leak through a sheet.
    const bool outside = dot(w, sp.ns) > 0;
    r.o = offset_ray_origin(outside ? sp.p_smooth : sp.p, sp.p_error, sp.ng,
                            outside ? sp.ng : -sp.ng);
    r.d = w;
    r.tmin = 0;
    r.tmax = std::numeric_limits<float>::infinity();
    if (std::isfinite(dist)) {
        // A shadow ray to a point: aimed from the moved origin at the point itself
        // (pbrt-v4's SpawnRayTo). Kept parallel to w, a lifted origin would carry the
        // segment's end past the point, into the area light sampled there, which then
        // blocks its own light (a smooth sphere under a panel lost 60% of its direct light).
        const Vec3 to = sp.p + w * dist - r.o;
        const float len = length(to);
        r.d = len > 0 ? to / len : w;
        r.tmax = len * (1 - 1e-4f);
    }
    r.time = time;
    return r;
}

}  // namespace penumbra
