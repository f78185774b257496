// Motion over the shutter: transforms and vertices at a normalized time u in [0, 1], from
// the time steps of Instance::motion, CameraDesc::motion and TriangleMesh::motion_*.
// Transforms are interpolated exactly as Embree 3.13.5 interpolates instances given by
// rtcSetGeometryTransformQuaternion, so every accelerator sees the same motion.
#pragma once

#include <cstdint>
#include <vector>

#include "core/math/bounds.h"
#include "core/math/transform.h"
#include "core/scene/scene.h"

namespace penumbra {

// Embree's RTCQuaternionDecomposition of an affine map: M = T * R * S, with T the
// translation, R the rotation of the unit quaternion (r, i, j, k) and S upper triangular
//   [scale.x skew.x  skew.y  shift.x]
//   [0       scale.y skew.z  shift.y]      skew = (xy, xz, yz)
//   [0       0       scale.z shift.z].
// A mirrored map (negative determinant) has a negative scale.z; R is always proper.
struct QuatDecomposition {
    Vec3 scale{1, 1, 1};
    Vec3 skew{0, 0, 0};
    Vec3 shift{0, 0, 0};
    float r = 1, i = 0, j = 0, k = 0;
    Vec3 translation{0, 0, 0};
};

// QR decomposition of the affine part (modified Gram-Schmidt in double): R = Q with a
// proper rotation, S = the triangular factor, shift 0, translation = m's last column.
QuatDecomposition decompose(const Mat4& m);
// The decompositions of time steps, each quaternion on the same side of the 4D sphere as
// its predecessor (q and -q are the same rotation; Embree's slerp flips anyway, but
// consistent signs keep the data meaning the shortest arc).
std::vector<QuatDecomposition> decompose_steps(const std::vector<Transform>& steps);
// T * R(q) * S as Embree's quaternionDecompositionToAffineSpace builds it (the rotation
// matrix from the homogeneous quaternion formula, unnormalized).
Mat4 compose(const QuatDecomposition& d);

// Embree's time segment: K steps make K - 1 segments; u in [0, 1] lies in segment
// floor(u (K - 1)), clamped to the last, at fraction f (Embree's getTimeSegment).
int time_segment(float u, int steps, float* f);
// Embree's slerp(AffineSpace3ff, AffineSpace3ff, t): all scale/skew/shift/translation
// fields linearly, the quaternion by its slerp (fast acos/sincos approximations, sign
// flip to the shorter arc, normalized lerp when the angle is below acos(0.9995)).
Mat4 interpolate(const QuatDecomposition& a, const QuatDecomposition& b, float f);
// The matrix at time u of pre-decomposed steps (size >= 2).
Mat4 motion_matrix_at(const std::vector<QuatDecomposition>& steps, float u);

// Transforms at time u: to_world for a static instance/camera, else the interpolated
// motion (with its inverse). Decomposes only the two steps around u.
Transform instance_transform_at(const Instance& inst, float u);
Transform camera_transform_at(const CameraDesc& camera, float u);
Mat4 transform_matrix_at(const std::vector<Transform>& steps, float u);

// Vertex v of a deforming mesh at time u, linear between steps (Embree's rule); the
// static positions/normals when the mesh does not deform.
Vec3 position_at(const TriangleMesh& mesh, uint32_t v, float u);
Vec3 normal_at(const TriangleMesh& mesh, uint32_t v, float u);
// Lerp as Embree's lerp(v0, v1, t) = (1 - t) v0 + t v1, in float.
inline Vec3 lerp_step(Vec3 a, Vec3 b, float f) { return a * (1 - f) + b * f; }

// A box that contains box transformed by the motion at every time u in [0, 1].
// Unions of the boxes at the steps are not enough: a slerped rotation sweeps points
// along arcs that bulge out of the chord. Each segment is cut into pieces; over a piece
// [ua, ub] with middle um, x(u) = R(u) y(u) + T(u) with y = S(u) p linear in u, so
//   x(u) in R(um) Y + box(T(ua), T(ub)) + ball(|R(u) - R(um)| max|y|),
// Y = box(S(ua) box, S(ub) box), and |R(u) - R(um)| <= the angle between them, bounded by
// the piece's half length times the interpolation's largest angular speed. A relative
// pad covers the float evaluation and Embree's approximate acos/sincos.
Bounds3 motion_bounds(const std::vector<QuatDecomposition>& steps, const Bounds3& box);

// True when any instance, mesh or camera of the scene has time steps.
bool scene_has_motion(const Scene& scene);

}  // namespace penumbra
