#include "study/accel_check.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "core/sampling/rng.h"
#include "core/sampling/warp.h"
#include "core/scene/motion.h"
#include "core/surface_point.h"

namespace penumbra {

const char* ray_kind_name(RayKind kind) {
    switch (kind) {
        case RayKind::Camera:
            return "camera";
        case RayKind::Random:
            return "random";
        case RayKind::Shadow:
            return "shadow";
        case RayKind::Bounce:
            return "bounce";
    }
    return "?";
}

const char* disagreement_name(Disagreement d) {
    switch (d) {
        case Disagreement::None:
            return "none";
        case Disagreement::EdgeOrVertex:
            return "edge/vertex";
        case Disagreement::Grazing:
            return "grazing";
        case Disagreement::Coincident:
            return "coincident";
        case Disagreement::Other:
            return "other";
    }
    return "?";
}

namespace {

Vec3 random_point(Rng& rng, const Bounds3& b) {
    // Braces: the three draws in order on every compiler (a call's arguments are not).
    const Vec3 u{rng.next_float(), rng.next_float(), rng.next_float()};
    return b.lo + b.diagonal() * u;
}

}  // namespace

std::vector<CheckRay> make_random_rays(const Scene& scene, size_t count, uint64_t seed) {
    Bounds3 b = scene.bounds();
    if (b.empty()) b.expand(Vec3(0.0f));
    // The same margin on every axis, so that a flat scene's origins are not all in its
    // plane.
    const Vec3 grow(std::max(0.1f * length(b.diagonal()), 1e-3f));
    b.lo -= grow;
    b.hi += grow;
    Rng rng(seed, 2);
    // Times from their own stream, so a static scene's rays stay as they were.
    Rng time_rng(seed, 3);
    const bool moves = scene_has_motion(scene);
    std::vector<CheckRay> rays(count);
    for (CheckRay& r : rays) {
        r.ray.o = random_point(rng, b);
        r.ray.d = square_to_uniform_sphere({rng.next_float(), rng.next_float()});
        if (moves) r.ray.time = time_rng.next_float();
        r.kind = RayKind::Random;
    }
    return rays;
}

std::vector<CheckRay> make_check_rays(const Scene& scene, const Camera& camera,
                                      const Accel& reference, const CheckRayOptions& options) {
    std::vector<CheckRay> rays;
    Rng rng(options.seed, 1);
    Rng time_rng(options.seed, 4);
    const bool moves = scene_has_motion(scene);
    for (int y = 0; y < camera.height(); ++y)
        for (int x = 0; x < camera.width(); ++x) {
            CameraSample cs;
            cs.film = {x + rng.next_float(), y + rng.next_float()};
            cs.lens = {rng.next_float(), rng.next_float()};
            if (moves) cs.time = time_rng.next_float();
            rays.push_back({camera.generate_ray(cs), RayKind::Camera});
        }
    const size_t camera_rays = rays.size();
    const std::vector<CheckRay> random = make_random_rays(scene, options.random, options.seed);
    rays.insert(rays.end(), random.begin(), random.end());

    // Surface rays start where the reference's camera rays hit, like a path's second
    // vertex: shadow rays to random points (a light anywhere), bounce rays anywhere.
    // A path keeps its camera ray's time: surface rays leave the point where the surface
    // was at that time, at that time.
    std::vector<SurfacePoint> points;
    std::vector<float> times;
    for (size_t i = 0; i < camera_rays; ++i)
        if (const auto hit = reference.intersect(rays[i].ray)) {
            points.push_back(make_surface_point(scene, rays[i].ray, *hit));
            times.push_back(rays[i].ray.time);
        }
    if (points.empty()) return rays;
    const Bounds3 bounds = scene.bounds();
    for (size_t i = 0; i < options.shadow; ++i) {
        const uint32_t k = rng.next_below(static_cast<uint32_t>(points.size()));
        const SurfacePoint& sp = points[k];
        const Vec3 to = random_point(rng, bounds) - sp.p;
        const float dist = length(to);
        if (!(dist > 0)) continue;
        rays.push_back({spawn_ray(sp, to / dist, dist, times[k]), RayKind::Shadow});
    }
    for (size_t i = 0; i < options.bounce; ++i) {
        const uint32_t k = rng.next_below(static_cast<uint32_t>(points.size()));
        const SurfacePoint& sp = points[k];
        const Vec3 w = square_to_uniform_sphere({rng.next_float(), rng.next_float()});
        rays.push_back({spawn_ray(sp, w, std::numeric_limits<float>::infinity(), times[k]),
                        RayKind::Bounce});
    }
    return rays;
}

TraceResults trace_rays(const Accel& accel, const std::vector<CheckRay>& rays) {
    TraceResults r;
    r.hits.resize(rays.size());
    r.occluded.assign(rays.size(), 0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 1024),
                      [&](const tbb::blocked_range<size_t>& range) {
                          for (size_t i = range.begin(); i != range.end(); ++i) {
                              r.hits[i] = accel.intersect(rays[i].ray);
                              if (rays[i].kind == RayKind::Shadow)
                                  r.occluded[i] = accel.occluded(rays[i].ray) ? 1 : 0;
                          }
                      });
    return r;
}

namespace {

float min_barycentric(const Hit& h) { return std::min({1 - h.b1 - h.b2, h.b1, h.b2}); }

bool is_grazing(const Scene& scene, const Ray& ray, const Hit& h) {
    const SurfacePoint sp = make_surface_point(scene, ray, h);
    return std::abs(dot(normalize(ray.d), sp.ng)) < kGrazingCos;
}

// Where the ray meets the hit triangle's plane, in double precision from the scene's
// own float data (vertices through the instance's forward matrix, both at the ray's
// time): the reference for judging t, the angle, and whether a point lies inside a
// triangle.
struct ExactHit {
    double t = 0, cos = 1;
    double min_barycentric = 0;  // of the plane point; < 0: outside the triangle
    double p[3][3] = {};         // world-space vertices
    double longest_edge = 0;
    double min_altitude = 0;  // twice the area over the longest edge

    // The world point that barycentrics (b1, b2) name on this triangle.
    void point(const Hit& h, double out[3]) const {
        for (int r = 0; r < 3; ++r)
            out[r] = p[0][r] * (1.0 - h.b1 - h.b2) + p[1][r] * h.b1 + p[2][r] * h.b2;
    }
};

ExactHit exact_plane_hit(const Scene& scene, const Ray& ray, const Hit& h) {
    const TriangleMesh& mesh = scene.meshes[h.mesh];
    const Transform xf = instance_transform_at(scene.instances[h.instance], ray.time);
    const Mat4& m = xf.matrix();
    ExactHit x;
    auto& p = x.p;
    for (int k = 0; k < 3; ++k) {
        const Vec3 v = position_at(mesh, mesh.indices[3 * h.prim + k], ray.time);
        for (int r = 0; r < 3; ++r)
            p[k][r] =
                double(m(r, 0)) * v.x + double(m(r, 1)) * v.y + double(m(r, 2)) * v.z + m(r, 3);
    }
    auto sub = [](const double* a, const double* b, double* out) {
        for (int r = 0; r < 3; ++r) out[r] = a[r] - b[r];
    };
    auto cross3 = [](const double* a, const double* b, double* out) {
        out[0] = a[1] * b[2] - a[2] * b[1];
        out[1] = a[2] * b[0] - a[0] * b[2];
        out[2] = a[0] * b[1] - a[1] * b[0];
    };
    auto dot3 = [](const double* a, const double* b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    };
    double e1[3], e2[3], n[3], o[3] = {ray.o.x, ray.o.y, ray.o.z},
                               d[3] = {ray.d.x, ray.d.y, ray.d.z}, q0[3];
    sub(p[1], p[0], e1);
    sub(p[2], p[0], e2);
    cross3(e1, e2, n);
    sub(p[0], o, q0);
    const double nn = dot3(n, n), nd = dot3(n, d);
    for (int k = 0; k < 3; ++k) {
        double e[3];
        sub(p[(k + 1) % 3], p[k], e);
        x.longest_edge = std::max(x.longest_edge, std::sqrt(dot3(e, e)));
    }
    x.min_altitude = x.longest_edge > 0 ? std::sqrt(nn) / x.longest_edge : 0;
    x.t = dot3(n, q0) / nd;
    x.cos = nd / std::sqrt(nn * dot3(d, d));
    // Barycentrics of the plane point: signed areas of the sub-triangles over the whole.
    double q[3], b[3];
    for (int r = 0; r < 3; ++r) q[r] = o[r] + x.t * d[r];
    for (int k = 0; k < 3; ++k) {
        double edge[3], to_q[3], c[3];
        sub(p[(k + 2) % 3], p[(k + 1) % 3], edge);
        sub(q, p[(k + 1) % 3], to_q);
        cross3(edge, to_q, c);
        b[k] = dot3(n, c) / nn;
    }
    x.min_barycentric = std::min({b[0], b[1], b[2]});
    if (!std::isfinite(x.min_barycentric)) x.min_barycentric = -1;
    return x;
}

std::string describe(const Scene& scene, const Ray& ray, const std::optional<Hit>& h) {
    if (!h) return "miss";
    const ExactHit x = exact_plane_hit(scene, ray, *h);
    char buf[240];
    std::snprintf(buf, sizeof buf,
                  "instance %u mesh %u prim %u t=%.9g b=(%.6g, %.6g) [double: t=%.9g cos=%.3g "
                  "min b=%.3g]",
                  h->instance, h->mesh, h->prim, h->t, h->b1, h->b2, x.t, x.cos, x.min_barycentric);
    return buf;
}

}  // namespace

float t_tolerance(const Ray& ray, float t, float cos) {
    const Vec3 p = ray.o + ray.d * t;
    float m = 0;
    for (int a = 0; a < 3; ++a) m = std::max({m, std::abs(ray.o[a]), std::abs(p[a])});
    const float c = std::max(std::abs(cos), kGrazingCos);
    return kCheckTRelTolerance * std::abs(t) + kCheckTUlps * 0x1p-24f * m / (length(ray.d) * c);
}

namespace {

// Near an edge: within kEdgeBarycentric of one, or within the distance a t error of
// t_tolerance moves the hit along the ray (the same error model), over the triangle's
// smallest altitude: at shallow angles the hit point is uncertain by that much.
bool near_edge(const Ray& ray, const Hit& h, const ExactHit& x) {
    const double along = double(t_tolerance(ray, h.t, float(x.cos))) * length(ray.d);
    const double slack = x.min_altitude > 0 ? along / x.min_altitude : 1.0;
    return min_barycentric(h) < kEdgeBarycentric + slack;
}

// Whether `mine` is right in double precision: a hit inside its triangle, or a miss
// when the other side's hit is outside its own.
bool answer_is_exact(const Scene& scene, const Ray& ray, const std::optional<Hit>& mine,
                     const std::optional<Hit>& other) {
    if (mine) return exact_plane_hit(scene, ray, *mine).min_barycentric >= 0;
    return other && exact_plane_hit(scene, ray, *other).min_barycentric < 0;
}

}  // namespace

Disagreement classify_hits(const Scene& scene, const Ray& ray, const std::optional<Hit>& a,
                           const std::optional<Hit>& b) {
    if (!a && !b) return Disagreement::None;
    ExactHit xa, xb;
    if (a) xa = exact_plane_hit(scene, ray, *a);
    if (b) xb = exact_plane_hit(scene, ray, *b);
    bool same = false, t_close = false;
    if (a && b) {
        same = a->instance == b->instance && a->mesh == b->mesh && a->prim == b->prim;
        const double cos = std::min(std::abs(xa.cos), std::abs(xb.cos));
        const float tol = t_tolerance(ray, std::max(std::abs(a->t), std::abs(b->t)),
                                      std::isfinite(cos) ? float(cos) : 1.0f);
        t_close = std::abs(a->t - b->t) <= tol;
        if (same && t_close) {
            double pa[3], pb[3], dist2 = 0;
            xa.point(*a, pa);
            xa.point(*b, pb);
            for (int r = 0; r < 3; ++r) dist2 += (pa[r] - pb[r]) * (pa[r] - pb[r]);
            const double allowed =
                double(tol) * length(ray.d) + double(kCheckBaryTolerance) * xa.longest_edge;
            if (std::sqrt(dist2) <= allowed) return Disagreement::None;
        }
        // Two triangles at the same t, and the ray passes through the inside of both (in
        // double precision, by more than its rounding): they overlap there, and both
        // answers are right.
        if (!same && t_close && xa.min_barycentric > kOverlapBarycentric &&
            xb.min_barycentric > kOverlapBarycentric)
            return Disagreement::Coincident;
    }
    if ((a && near_edge(ray, *a, xa)) || (b && near_edge(ray, *b, xb)))
        return Disagreement::EdgeOrVertex;
    if ((a && is_grazing(scene, ray, *a)) || (b && is_grazing(scene, ray, *b)))
        return Disagreement::Grazing;
    return Disagreement::Other;
}

namespace {

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool identical(const std::optional<Hit>& a, const std::optional<Hit>& b) {
    if (!a || !b) return !a && !b;
    return a->instance == b->instance && a->mesh == b->mesh && a->prim == b->prim &&
           same_bits(a->t, b->t) && same_bits(a->b1, b->b1) && same_bits(a->b2, b->b2);
}

}  // namespace

AgreementReport compare_results(const Scene& scene, const std::vector<CheckRay>& rays,
                                const TraceResults& reference, const TraceResults& test,
                                const std::string& reference_name, const std::string& test_name,
                                size_t examples_per_class) {
    AgreementReport rep;
    rep.name = test_name;
    rep.rays = rays.size();
    for (size_t i = 0; i < rays.size(); ++i) {
        const Ray& ray = rays[i].ray;
        const std::optional<Hit>& a = reference.hits[i];
        const std::optional<Hit>& b = test.hits[i];
        rep.not_identical += !identical(a, b) || reference.occluded[i] != test.occluded[i];
        Disagreement d = classify_hits(scene, ray, a, b);
        std::string what = "closest hit";
        if (d == Disagreement::None && rays[i].kind == RayKind::Shadow &&
            reference.occluded[i] != test.occluded[i]) {
            // The side that says "occluded" must have a closest hit to blame.
            const std::optional<Hit>& h = reference.occluded[i] ? a : b;
            d = h ? classify_hits(scene, ray, h, std::nullopt) : Disagreement::Other;
            what = std::string("occluded: ") + reference_name + " " +
                   (reference.occluded[i] ? "yes" : "no") + ", " + test_name + " " +
                   (test.occluded[i] ? "yes" : "no") + "; closest hit";
        }
        const uint64_t seen = ++rep.per_class[static_cast<int>(d)];
        if (d == Disagreement::None) continue;
        if (d == Disagreement::EdgeOrVertex) {
            const bool ref_right = answer_is_exact(scene, ray, a, b);
            const bool test_right = answer_is_exact(scene, ray, b, a);
            rep.edge_reference_right += ref_right && !test_right;
            rep.edge_test_right += test_right && !ref_right;
        }
        ++rep.per_kind[static_cast<int>(rays[i].kind)];
        if (seen <= examples_per_class) {
            char buf[256];
            std::snprintf(buf, sizeof buf,
                          "%s ray %zu, o=(%.9g, %.9g, %.9g) d=(%.9g, %.9g, %.9g) t in [%g, %g]",
                          ray_kind_name(rays[i].kind), i, ray.o.x, ray.o.y, ray.o.z, ray.d.x,
                          ray.d.y, ray.d.z, ray.tmin, ray.tmax);
            rep.examples.push_back(std::string(disagreement_name(d)) + ": " + buf + ": " + what +
                                   ": " + reference_name + " " + describe(scene, ray, a) + "; " +
                                   test_name + " " + describe(scene, ray, b));
        }
    }
    return rep;
}

}  // namespace penumbra
