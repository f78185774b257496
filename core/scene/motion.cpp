#include "core/scene/motion.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace penumbra {

namespace {

struct Quatf {
    float r, i, j, k;
};

float dot(const Quatf& a, const Quatf& b) { return a.r * b.r + a.i * b.i + a.j * b.j + a.k * b.k; }
Quatf scaled(const Quatf& a, float s) { return {a.r * s, a.i * s, a.j * s, a.k * s}; }
Quatf normalized(const Quatf& a) { return scaled(a, 1.0f / std::sqrt(dot(a, a))); }
float lerp1(float a, float b, float f) { return (1 - f) * a + f * b; }

// Embree's fastapprox::asin/acos (common/math/transcendental.h, from ispc/syrah): a
// degree-5 minimax polynomial in |x| times sqrt(1 - |x|). Reproduced, not replaced by
// std::acos, so that our slerp lands where Embree's does.
float fast_acos(float x0) {
    const float x = std::abs(x0);
    float v = 1.57079517841339111328125f +
              x * (-0.21450997889041900634765625f +
                   x * (8.78556668758392333984375e-2f +
                        x * (-4.489909112453460693359375e-2f +
                             x * (1.928029954433441162109375e-2f +
                                  x * (-4.3095736764371395111083984375e-3f)))));
    v *= -std::sqrt(1.0f - x);
    v = v + 1.57079637050628662109375f;
    if (v < 0) v = 0;
    if (x0 < 0) v = -v;
    return 1.57079637050628662109375f - v;
}

// Embree's fastapprox::sincos: reduction by pi/2 and degree-10 even/odd polynomials.
void fast_sincos(float v, float* s, float* c) {
    const float kPiOver2 = 1.57079637050628662109375f;
    const float kTwoOverPi = 0.636619746685028076171875f;
    const float k_real = std::floor(v * kTwoOverPi);
    const int k = static_cast<int>(k_real);
    const float x = v - k_real * kPiOver2;
    const int m = k & 3;
    const float x2 = x * x;
    float sf = x2 * -2.50293279435709337121807038784027099609375e-8f +
               2.760012648650445044040679931640625e-6f;
    float cf = x2 * -2.59630184018533327616751194000244140625e-7f +
               2.47562347794882953166961669921875e-5f;
    sf = x2 * sf + -1.9842604524455964565277099609375e-4f;
    cf = x2 * cf + -1.388833043165504932403564453125e-3f;
    sf = x2 * sf + 8.333347737789154052734375e-3f;
    cf = x2 * cf + 4.166664183139801025390625e-2f;
    sf = x2 * sf + -0.16666667163372039794921875f;
    cf = x2 * cf + -0.5f;
    sf = x2 * sf + 1.0f;
    cf = x2 * cf + 1.0f;
    sf *= x;
    float sin_r = (m == 1 || m == 3) ? cf : sf;
    float cos_r = (m == 0 || m == 2) ? cf : sf;
    if (m > 1) sin_r = -sin_r;
    if (m == 1 || m == 2) cos_r = -cos_r;
    *s = sin_r;
    *c = cos_r;
}

// Embree's quaternion slerp (common/math/quaternion.h).
Quatf slerp(const Quatf& q0, const Quatf& q1_in, float t) {
    float cos_theta = dot(q0, q1_in);
    const Quatf q1 = cos_theta < 0 ? scaled(q1_in, -1) : q1_in;
    cos_theta = std::abs(cos_theta);
    if (cos_theta > 0.9995f)
        return normalized(Quatf{lerp1(q0.r, q1.r, t), lerp1(q0.i, q1.i, t),
                                lerp1(q0.j, q1.j, t), lerp1(q0.k, q1.k, t)});
    const float phi = t * fast_acos(cos_theta);
    float sin_phi, cos_phi;
    fast_sincos(phi, &sin_phi, &cos_phi);
    const Quatf perp = scaled(normalized(Quatf{cos_theta * q0.r - q1.r, cos_theta * q0.i - q1.i,
                                               cos_theta * q0.j - q1.j, cos_theta * q0.k - q1.k}),
                              sin_phi);
    return {cos_phi * q0.r - perp.r, cos_phi * q0.i - perp.i, cos_phi * q0.j - perp.j,
            cos_phi * q0.k - perp.k};
}

// Columns of Embree's LinearSpace3(q): the homogeneous formula, exact for unit q.
void rotation_matrix(const Quatf& q, float R[3][3]) {
    const float rr = q.r * q.r, ii = q.i * q.i, jj = q.j * q.j, kk = q.k * q.k;
    R[0][0] = rr + ii - jj - kk;
    R[1][0] = 2 * (q.i * q.j + q.r * q.k);
    R[2][0] = 2 * (q.i * q.k - q.r * q.j);
    R[0][1] = 2 * (q.i * q.j - q.r * q.k);
    R[1][1] = rr - ii + jj - kk;
    R[2][1] = 2 * (q.j * q.k + q.r * q.i);
    R[0][2] = 2 * (q.i * q.k + q.r * q.j);
    R[1][2] = 2 * (q.j * q.k - q.r * q.i);
    R[2][2] = rr - ii - jj + kk;
}

Quatf quat_of(const QuatDecomposition& d) { return {d.r, d.i, d.j, d.k}; }

// T * R(q) * S with the S and T fields of d and the rotation q (Embree: D * R * S).
Mat4 compose_with(const QuatDecomposition& d, const Quatf& q) {
    float R[3][3];
    rotation_matrix(q, R);
    const float S[3][4] = {{d.scale.x, d.skew.x, d.skew.y, d.shift.x},
                           {0, d.scale.y, d.skew.z, d.shift.y},
                           {0, 0, d.scale.z, d.shift.z}};
    Mat4 m = Mat4::identity();
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 4; ++c)
            m(r, c) = R[r][0] * S[0][c] + R[r][1] * S[1][c] + R[r][2] * S[2][c];
        m(r, 3) += d.translation[r];
    }
    return m;
}

QuatDecomposition lerp_fields(const QuatDecomposition& a, const QuatDecomposition& b, float f) {
    QuatDecomposition d;
    d.scale = lerp_step(a.scale, b.scale, f);
    d.skew = lerp_step(a.skew, b.skew, f);
    d.shift = lerp_step(a.shift, b.shift, f);
    d.translation = lerp_step(a.translation, b.translation, f);
    return d;
}

// Rotation matrix (columns c0, c1, c2, proper) to a unit quaternion in Embree's
// convention, choosing the largest of r, i, j, k to divide by (Shepperd 1978).
Quatf quaternion_from_rotation(const double c[3][3]) {
    // c[col][row]
    const double xx = c[0][0], yy = c[1][1], zz = c[2][2];
    double r, i, j, k;
    const double tr = xx + yy + zz;
    if (tr >= 0) {
        const double s = 0.5 / std::sqrt(1 + tr);
        r = 0.25 / s;
        i = (c[1][2] - c[2][1]) * s;
        j = (c[2][0] - c[0][2]) * s;
        k = (c[0][1] - c[1][0]) * s;
    } else if (xx >= std::max(yy, zz)) {
        const double s = 0.5 / std::sqrt(1 + xx - yy - zz);
        i = 0.25 / s;
        r = (c[1][2] - c[2][1]) * s;
        j = (c[0][1] + c[1][0]) * s;
        k = (c[2][0] + c[0][2]) * s;
    } else if (yy >= zz) {
        const double s = 0.5 / std::sqrt(1 + yy - zz - xx);
        j = 0.25 / s;
        r = (c[2][0] - c[0][2]) * s;
        i = (c[0][1] + c[1][0]) * s;
        k = (c[1][2] + c[2][1]) * s;
    } else {
        const double s = 0.5 / std::sqrt(1 + zz - xx - yy);
        k = 0.25 / s;
        r = (c[0][1] - c[1][0]) * s;
        i = (c[2][0] + c[0][2]) * s;
        j = (c[1][2] + c[2][1]) * s;
    }
    const double n = std::sqrt(r * r + i * i + j * j + k * k);
    return {float(r / n), float(i / n), float(j / n), float(k / n)};
}

void align_sign(const QuatDecomposition& prev, QuatDecomposition* d) {
    if (dot(quat_of(prev), quat_of(*d)) < 0) {
        d->r = -d->r;
        d->i = -d->i;
        d->j = -d->j;
        d->k = -d->k;
    }
}

}  // namespace

QuatDecomposition decompose(const Mat4& m) {
    double a[3][3];  // a[col][row]
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) a[c][r] = m(r, c);
    auto dot3 = [](const double* x, const double* y) {
        return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
    };
    double q[3][3], u[3][3] = {};
    // Modified Gram-Schmidt: column c of A = sum_{r <= c} q_r u[r][c].
    for (int c = 0; c < 3; ++c) {
        double v[3] = {a[c][0], a[c][1], a[c][2]};
        for (int r = 0; r < c; ++r) {
            u[r][c] = dot3(q[r], v);
            for (int x = 0; x < 3; ++x) v[x] -= u[r][c] * q[r][x];
        }
        u[c][c] = std::sqrt(dot3(v, v));
        CHECK(u[c][c] > 0, "decompose: singular transform");
        for (int x = 0; x < 3; ++x) q[c][x] = v[x] / u[c][c];
    }
    // A mirror: Q has determinant -1. Negating its last column and the last row of the
    // triangular factor (only u[2][2]) keeps Q R = A with Q a rotation.
    const double cr[3] = {q[0][1] * q[1][2] - q[0][2] * q[1][1],
                          q[0][2] * q[1][0] - q[0][0] * q[1][2],
                          q[0][0] * q[1][1] - q[0][1] * q[1][0]};
    if (dot3(cr, q[2]) < 0) {
        for (int x = 0; x < 3; ++x) q[2][x] = -q[2][x];
        u[2][2] = -u[2][2];
    }
    QuatDecomposition d;
    d.scale = Vec3(float(u[0][0]), float(u[1][1]), float(u[2][2]));
    d.skew = Vec3(float(u[0][1]), float(u[0][2]), float(u[1][2]));
    d.shift = Vec3(0, 0, 0);
    const Quatf qq = quaternion_from_rotation(q);
    d.r = qq.r;
    d.i = qq.i;
    d.j = qq.j;
    d.k = qq.k;
    d.translation = Vec3(m(0, 3), m(1, 3), m(2, 3));
    return d;
}

std::vector<QuatDecomposition> decompose_steps(const std::vector<Transform>& steps) {
    std::vector<QuatDecomposition> out;
    out.reserve(steps.size());
    for (const Transform& t : steps) {
        out.push_back(decompose(t.matrix()));
        if (out.size() > 1) align_sign(out[out.size() - 2], &out.back());
    }
    return out;
}

Mat4 compose(const QuatDecomposition& d) { return compose_with(d, quat_of(d)); }

int time_segment(float u, int steps, float* f) {
    const float segments = static_cast<float>(steps - 1);
    const float scaled = u * segments;
    const float seg = std::clamp(std::floor(scaled), 0.0f, segments - 1.0f);
    *f = scaled - seg;
    return static_cast<int>(seg);
}

Mat4 interpolate(const QuatDecomposition& a, const QuatDecomposition& b, float f) {
    return compose_with(lerp_fields(a, b, f), slerp(quat_of(a), quat_of(b), f));
}

Mat4 motion_matrix_at(const std::vector<QuatDecomposition>& steps, float u) {
    float f;
    const int s = time_segment(u, static_cast<int>(steps.size()), &f);
    return interpolate(steps[s], steps[s + 1], f);
}

Mat4 transform_matrix_at(const std::vector<Transform>& steps, float u) {
    float f;
    const int s = time_segment(u, static_cast<int>(steps.size()), &f);
    const QuatDecomposition a = decompose(steps[s].matrix());
    QuatDecomposition b = decompose(steps[s + 1].matrix());
    align_sign(a, &b);
    return interpolate(a, b, f);
}

Transform instance_transform_at(const Instance& inst, float u) {
    if (inst.motion.empty()) return inst.to_world;
    return Transform(transform_matrix_at(inst.motion, u));
}

Transform camera_transform_at(const CameraDesc& camera, float u) {
    if (camera.motion.empty()) return camera.to_world;
    return Transform(transform_matrix_at(camera.motion, u));
}

Vec3 position_at(const TriangleMesh& mesh, uint32_t v, float u) {
    if (mesh.motion_positions.empty()) return mesh.positions[v];
    float f;
    const int s = time_segment(u, static_cast<int>(mesh.motion_positions.size()), &f);
    return lerp_step(mesh.motion_positions[s][v], mesh.motion_positions[s + 1][v], f);
}

Vec3 normal_at(const TriangleMesh& mesh, uint32_t v, float u) {
    if (mesh.motion_normals.empty()) return mesh.normals[v];
    float f;
    const int s = time_segment(u, static_cast<int>(mesh.motion_normals.size()), &f);
    return lerp_step(mesh.motion_normals[s][v], mesh.motion_normals[s + 1][v], f);
}

Bounds3 motion_bounds(const std::vector<QuatDecomposition>& steps, const Bounds3& box) {
    Bounds3 out;
    if (box.empty()) return out;
    auto corners = [](const Bounds3& b, int c) {
        return Vec3(c & 1 ? b.hi.x : b.lo.x, c & 2 ? b.hi.y : b.lo.y, c & 4 ? b.hi.z : b.lo.z);
    };
    for (size_t s = 0; s + 1 < steps.size(); ++s) {
        const QuatDecomposition& a = steps[s];
        const QuatDecomposition& b = steps[s + 1];
        // Quaternion angle between the steps (after the sign flip slerp does).
        const double cos_theta =
            std::min(1.0, std::abs(double(dot(quat_of(a), quat_of(b)))));
        const double theta = std::acos(cos_theta);
        // Largest rate of the rotation angle per unit f: 2 theta for slerp; the
        // normalized lerp fallback turns at most 2 tan(theta / 2) per unit in quaternion
        // angle (fastest at the middle), twice that in rotation angle. 4 tan(theta/2) >=
        // 2 theta covers both.
        const double speed = 4 * std::tan(0.5 * theta);
        // Pieces so that the first-order margin stays near 1% of the radius.
        const int pieces = std::clamp(int(std::ceil(theta / 0.005)), 1, 64);
        for (int p = 0; p < pieces; ++p) {
            const float ua = float(p) / pieces, ub = float(p + 1) / pieces;
            const float um = 0.5f * (ua + ub);
            Bounds3 Y;  // S(u) box over the piece: S is linear in u
            Bounds3 T;
            for (float uu : {ua, ub}) {
                const QuatDecomposition d = lerp_fields(a, b, uu);
                const Quatf one{1, 0, 0, 0};
                const Mat4 S = compose_with(QuatDecomposition{d.scale, d.skew, d.shift},
                                            one);
                for (int c = 0; c < 8; ++c) {
                    const Vec3 p0 = corners(box, c);
                    Vec3 y;
                    for (int r = 0; r < 3; ++r)
                        y[r] = S(r, 0) * p0.x + S(r, 1) * p0.y + S(r, 2) * p0.z + S(r, 3);
                    Y.expand(y);
                }
                T.expand(d.translation);
            }
            float R[3][3];
            rotation_matrix(slerp(quat_of(a), quat_of(b), um), R);
            Bounds3 RY;
            double radius = 0;
            for (int c = 0; c < 8; ++c) {
                const Vec3 y = corners(Y, c);
                radius = std::max(radius, double(length(y)));
                Vec3 x;
                for (int r = 0; r < 3; ++r) x[r] = R[r][0] * y.x + R[r][1] * y.y + R[r][2] * y.z;
                RY.expand(x);
            }
            const double half = 0.5 / pieces;
            // |R(u) - R(um)| <= rotation angle between them <= speed * half; plus a
            // relative 1e-4 for float rounding and Embree's approximate acos/sincos and
            // unnormalized quaternions (their errors are ~1e-6).
            const double t_scale = max_component(max(T.lo * -1.0f, T.hi));
            const float margin = float(speed * half * radius + 1e-4 * (radius + t_scale));
            Bounds3 piece;
            piece.lo = RY.lo + T.lo - Vec3(margin);
            piece.hi = RY.hi + T.hi + Vec3(margin);
            out.expand(piece);
        }
    }
    return out;
}

bool scene_has_motion(const Scene& scene) {
    for (const Instance& inst : scene.instances)
        if (!inst.motion.empty()) return true;
    for (const TriangleMesh& mesh : scene.meshes)
        if (!mesh.motion_positions.empty()) return true;
    for (const CameraDesc& cam : scene.cameras)
        if (!cam.motion.empty()) return true;
    return false;
}

}  // namespace penumbra
