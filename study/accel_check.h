// Cross-checking accelerators: the rays a check traces (camera, random and surface
// rays), every accelerator's answers to them, and the comparison of two sets of answers
// with each disagreement classified. `penumbra check-accel` and the tests share this.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/accel/accel.h"
#include "core/camera/camera.h"

namespace penumbra {

enum class RayKind { Camera, Random, Shadow, Bounce };
constexpr int kRayKinds = 4;
const char* ray_kind_name(RayKind kind);

struct CheckRay {
    Ray ray;
    RayKind kind;
};

struct CheckRayOptions {
    size_t random = 100000;  // rays from random points in the (enlarged) scene bounds
    size_t shadow = 100000;  // from camera-ray hits towards random points in the bounds
    size_t bounce = 100000;  // from camera-ray hits in uniformly random directions
    uint64_t seed = 1;
};

// One camera ray per pixel of `camera` (jittered in the pixel), then the random rays,
// then rays leaving the reference accelerator's camera hits (spawn_ray, so the origin
// is offset as the integrators do it). Deterministic for a given seed.
std::vector<CheckRay> make_check_rays(const Scene& scene, const Camera& camera,
                                      const Accel& reference, const CheckRayOptions& options);
// Only the random rays: origins uniform in the scene bounds grown by 10% of the
// diagonal's length on every side, directions uniform on the sphere.
std::vector<CheckRay> make_random_rays(const Scene& scene, size_t count, uint64_t seed);

// An accelerator's answers: intersect() for every ray, occluded() for shadow rays.
struct TraceResults {
    std::vector<std::optional<Hit>> hits;
    std::vector<uint8_t> occluded;  // 0/1; only meaningful for shadow rays
};
TraceResults trace_rays(const Accel& accel, const std::vector<CheckRay>& rays);

// How two answers to one ray differ:
//   Coincident:   both hit different triangles at the same t (within tolerance), and the
//                 ray passes through the inside of both (min barycentric, recomputed in
//                 double, > kOverlapBarycentric): the faces overlap; both answers are right.
//   EdgeOrVertex: otherwise, a hit has min(b0, b1, b2) < kEdgeBarycentric, plus the hit
//                 point's own uncertainty (the t tolerance along the ray) over the
//                 triangle's smallest altitude: the ray passes within rounding of an edge
//                 or vertex, where either triangle may win.
//   Grazing:      otherwise, |cos| between the ray and a hit's normal < kGrazingCos.
//   Other:        anything else; expected never to happen.
enum class Disagreement { None, EdgeOrVertex, Grazing, Coincident, Other };
constexpr int kDisagreementKinds = 5;
const char* disagreement_name(Disagreement d);
// t agrees when |t1 - t2| <= 1e-4 max(t1, t2) + 16 eps M / (|d| |cos|), eps = 2^-24.
// The second term is float's own limit: the origin and the vertices (magnitude M: the
// larger of the origin and the hit point) carry rounding errors of a few eps M, which
// move the plane the ray meets by that much along its normal, hence t by that much over
// |d| |cos| (cos: between the ray and the triangle's normal, at least kGrazingCos). It
// matters near the origin (tiny t) and at shallow angles, nowhere else.
constexpr float kCheckTRelTolerance = 1e-4f;
constexpr float kCheckTUlps = 16.0f;
// Same triangle: the points the two barycentric pairs name may be apart by the t
// tolerance (times |d|: a t error moves the hit along the ray, which at a shallow angle
// is across the triangle) plus 1e-3 of the triangle's longest edge. A swapped or
// misordered barycentric pair moves the point by a good part of the triangle.
constexpr float kCheckBaryTolerance = 1e-3f;
constexpr float kEdgeBarycentric = 1e-4f;
constexpr double kOverlapBarycentric = 1e-9;  // above double rounding only
constexpr float kGrazingCos = 1e-3f;

// Same instance, mesh and triangle, t and barycentrics within tolerance: None.
// The largest |t1 - t2| that counts as agreement for hits near t; cos: the smaller |cos|
// of the two hits' triangles with the ray.
float t_tolerance(const Ray& ray, float t, float cos);
Disagreement classify_hits(const Scene& scene, const Ray& ray, const std::optional<Hit>& a,
                           const std::optional<Hit>& b);

struct AgreementReport {
    std::string name;  // the accelerator checked
    uint64_t rays = 0;
    uint64_t per_class[kDisagreementKinds] = {};  // index: Disagreement
    uint64_t per_kind[kRayKinds] = {};            // disagreeing rays by RayKind
    // Edge/vertex disagreements that double precision settles: the side whose answer is
    // right (a hit inside its triangle, or a miss where the other's hit is outside).
    uint64_t edge_reference_right = 0, edge_test_right = 0;
    // Rays whose answers are not bit for bit the same (any Hit field, or occluded()): the
    // measure for two runs of one accelerator, such as Embree under two ISAs.
    uint64_t not_identical = 0;
    std::vector<std::string> examples;  // the first few of each class

    uint64_t disagreements() const { return rays - per_class[0]; }
    uint64_t count(Disagreement d) const { return per_class[static_cast<int>(d)]; }
    // Counted against the threshold: the disagreements that could be the tested
    // accelerator's fault. Coincident faces give two right answers (each side's triangle
    // is hit at the same t), and an edge/vertex case that double precision settles in
    // the tested accelerator's favour is the reference's rounding (on scenes/instances.gltf
    // Embree's float world-to-object transform puts ~1.6e-5 of the rays on the wrong side
    // of an edge; our BVH applies the inverse in double). Both are reported, never counted.
    uint64_t counted() const {
        return disagreements() - count(Disagreement::Coincident) - edge_test_right;
    }
    // No "other" disagreement, and at most threshold * rays counted ones.
    bool passes(double threshold) const {
        return count(Disagreement::Other) == 0 && counted() <= threshold * double(rays);
    }
};

// Compares test against reference ray by ray. A ray disagrees when its intersect()
// answers do (classify_hits) or, for a shadow ray, when the occluded() answers differ
// (classified by the closest hit of whichever side says "occluded").
AgreementReport compare_results(const Scene& scene, const std::vector<CheckRay>& rays,
                                const TraceResults& reference, const TraceResults& test,
                                const std::string& reference_name, const std::string& test_name,
                                size_t examples_per_class = 3);

}  // namespace penumbra
