#include "core/math/transform.h"

#include <cmath>
#include <stdexcept>

namespace penumbra {

Mat4 Mat4::identity() {
    Mat4 r;
    for (int i = 0; i < 4; ++i) r.m[i][i] = 1;
    return r;
}

Mat4 Mat4::from_column_major(const double* v) {
    Mat4 r;
    for (int i = 0; i < 16; ++i) r.m[i % 4][i / 4] = static_cast<float>(v[i]);
    return r;
}

Mat4 Mat4::transposed() const {
    Mat4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r.m[i][j] = m[j][i];
    return r;
}

bool Mat4::is_identity() const {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (m[i][j] != (i == j ? 1.0f : 0.0f)) return false;
    return true;
}

double Mat4::determinant3x3() const {
    const double a = m[0][0], b = m[0][1], c = m[0][2];
    const double d = m[1][0], e = m[1][1], f = m[1][2];
    const double g = m[2][0], h = m[2][1], i = m[2][2];
    return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
}

bool Mat4::inverse(Mat4* out) const {
    // Cofactor expansion in double precision (the Mesa gluInvertMatrix layout).
    double a[16], inv[16];
    for (int i = 0; i < 16; ++i) a[i] = m[i / 4][i % 4];
    inv[0] = a[5] * a[10] * a[15] - a[5] * a[11] * a[14] - a[9] * a[6] * a[15] +
             a[9] * a[7] * a[14] + a[13] * a[6] * a[11] - a[13] * a[7] * a[10];
    inv[4] = -a[4] * a[10] * a[15] + a[4] * a[11] * a[14] + a[8] * a[6] * a[15] -
             a[8] * a[7] * a[14] - a[12] * a[6] * a[11] + a[12] * a[7] * a[10];
    inv[8] = a[4] * a[9] * a[15] - a[4] * a[11] * a[13] - a[8] * a[5] * a[15] +
             a[8] * a[7] * a[13] + a[12] * a[5] * a[11] - a[12] * a[7] * a[9];
    inv[12] = -a[4] * a[9] * a[14] + a[4] * a[10] * a[13] + a[8] * a[5] * a[14] -
              a[8] * a[6] * a[13] - a[12] * a[5] * a[10] + a[12] * a[6] * a[9];
    inv[1] = -a[1] * a[10] * a[15] + a[1] * a[11] * a[14] + a[9] * a[2] * a[15] -
             a[9] * a[3] * a[14] - a[13] * a[2] * a[11] + a[13] * a[3] * a[10];
    inv[5] = a[0] * a[10] * a[15] - a[0] * a[11] * a[14] - a[8] * a[2] * a[15] +
             a[8] * a[3] * a[14] + a[12] * a[2] * a[11] - a[12] * a[3] * a[10];
    inv[9] = -a[0] * a[9] * a[15] + a[0] * a[11] * a[13] + a[8] * a[1] * a[15] -
             a[8] * a[3] * a[13] - a[12] * a[1] * a[11] + a[12] * a[3] * a[9];
    inv[13] = a[0] * a[9] * a[14] - a[0] * a[10] * a[13] - a[8] * a[1] * a[14] +
              a[8] * a[2] * a[13] + a[12] * a[1] * a[10] - a[12] * a[2] * a[9];
    inv[2] = a[1] * a[6] * a[15] - a[1] * a[7] * a[14] - a[5] * a[2] * a[15] +
             a[5] * a[3] * a[14] + a[13] * a[2] * a[7] - a[13] * a[3] * a[6];
    inv[6] = -a[0] * a[6] * a[15] + a[0] * a[7] * a[14] + a[4] * a[2] * a[15] -
             a[4] * a[3] * a[14] - a[12] * a[2] * a[7] + a[12] * a[3] * a[6];
    inv[10] = a[0] * a[5] * a[15] - a[0] * a[7] * a[13] - a[4] * a[1] * a[15] +
              a[4] * a[3] * a[13] + a[12] * a[1] * a[7] - a[12] * a[3] * a[5];
    inv[14] = -a[0] * a[5] * a[14] + a[0] * a[6] * a[13] + a[4] * a[1] * a[14] -
              a[4] * a[2] * a[13] - a[12] * a[1] * a[6] + a[12] * a[2] * a[5];
    inv[3] = -a[1] * a[6] * a[11] + a[1] * a[7] * a[10] + a[5] * a[2] * a[11] -
             a[5] * a[3] * a[10] - a[9] * a[2] * a[7] + a[9] * a[3] * a[6];
    inv[7] = a[0] * a[6] * a[11] - a[0] * a[7] * a[10] - a[4] * a[2] * a[11] +
             a[4] * a[3] * a[10] + a[8] * a[2] * a[7] - a[8] * a[3] * a[6];
    inv[11] = -a[0] * a[5] * a[11] + a[0] * a[7] * a[9] + a[4] * a[1] * a[11] -
              a[4] * a[3] * a[9] - a[8] * a[1] * a[7] + a[8] * a[3] * a[5];
    inv[15] = a[0] * a[5] * a[10] - a[0] * a[6] * a[9] - a[4] * a[1] * a[10] +
              a[4] * a[2] * a[9] + a[8] * a[1] * a[6] - a[8] * a[2] * a[5];
    const double det = a[0] * inv[0] + a[1] * inv[4] + a[2] * inv[8] + a[3] * inv[12];
    if (det == 0 || !std::isfinite(det)) return false;
    const double s = 1.0 / det;
    for (int i = 0; i < 16; ++i) out->m[i / 4][i % 4] = static_cast<float>(inv[i] * s);
    return true;
}

Mat4 operator*(const Mat4& a, const Mat4& b) {
    Mat4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double s = 0;
            for (int k = 0; k < 4; ++k) s += double(a.m[i][k]) * b.m[k][j];
            r.m[i][j] = static_cast<float>(s);
        }
    return r;
}

Transform::Transform(const Mat4& m) : m_m(m) {
    if (!m.inverse(&m_inv)) throw std::invalid_argument("singular transform matrix");
    classify();
}

void Transform::classify() {
    auto translation = [](const Mat4& a) {
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 3; ++j)
                if (a.m[i][j] != (i == j ? 1.0f : 0.0f)) return false;
        return a.m[3][3] == 1.0f;
    };
    m_translation_only = translation(m_m) && translation(m_inv);
    m_affine = m_m.m[3][0] == 0 && m_m.m[3][1] == 0 && m_m.m[3][2] == 0 && m_m.m[3][3] == 1;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 3; ++r) m_columns[c][r] = m_m.m[r][c];
        m_columns[c][3] = 0;
    }
    m_swaps_handedness = m_m.determinant3x3() < 0;
}

Transform Transform::translate(Vec3 t) {
    Mat4 m = Mat4::identity(), inv = Mat4::identity();
    for (int i = 0; i < 3; ++i) {
        m.m[i][3] = t[i];
        inv.m[i][3] = -t[i];
    }
    return Transform(m, inv);
}

Transform Transform::scale(Vec3 s) {
    Mat4 m = Mat4::identity(), inv = Mat4::identity();
    for (int i = 0; i < 3; ++i) {
        m.m[i][i] = s[i];
        inv.m[i][i] = 1.0f / s[i];
    }
    if (s.x == 0 || s.y == 0 || s.z == 0) throw std::invalid_argument("zero scale");
    return Transform(m, inv);
}

Transform Transform::rotate(const Quat& q0) {
    // Normalize so that a slightly denormalized glTF quaternion stays a pure rotation.
    const float n = std::sqrt(q0.x * q0.x + q0.y * q0.y + q0.z * q0.z + q0.w * q0.w);
    if (!(n > 0)) throw std::invalid_argument("zero-length rotation quaternion");
    const float x = q0.x / n, y = q0.y / n, z = q0.z / n, w = q0.w / n;
    Mat4 m = Mat4::identity();
    m.m[0][0] = 1 - 2 * (y * y + z * z);
    m.m[0][1] = 2 * (x * y - z * w);
    m.m[0][2] = 2 * (x * z + y * w);
    m.m[1][0] = 2 * (x * y + z * w);
    m.m[1][1] = 1 - 2 * (x * x + z * z);
    m.m[1][2] = 2 * (y * z - x * w);
    m.m[2][0] = 2 * (x * z - y * w);
    m.m[2][1] = 2 * (y * z + x * w);
    m.m[2][2] = 1 - 2 * (x * x + y * y);
    return Transform(m, m.transposed());
}

Transform Transform::trs(Vec3 t, const Quat& r, Vec3 s) {
    return translate(t) * rotate(r) * scale(s);
}

Transform Transform::look_at(Vec3 eye, Vec3 target, Vec3 up) {
    const Vec3 back = normalize(eye - target);  // local +Z
    Vec3 right = cross(up, back);
    if (length_squared(right) < 1e-12f) right = cross(Vec3(1, 0, 0), back);
    if (length_squared(right) < 1e-12f) right = cross(Vec3(0, 0, 1), back);
    right = normalize(right);
    const Vec3 true_up = cross(back, right);
    Mat4 m = Mat4::identity();
    for (int i = 0; i < 3; ++i) {
        m.m[i][0] = right[i];
        m.m[i][1] = true_up[i];
        m.m[i][2] = back[i];
        m.m[i][3] = eye[i];
    }
    return Transform(m);
}

Bounds3 Transform::bounds(const Bounds3& b) const {
    Bounds3 r;
    if (b.empty()) return r;
    for (int c = 0; c < 8; ++c)
        r.expand(point({(c & 1) ? b.hi.x : b.lo.x, (c & 2) ? b.hi.y : b.lo.y,
                        (c & 4) ? b.hi.z : b.lo.z}));
    return r;
}

Transform operator*(const Transform& a, const Transform& b) {
    return Transform(a.matrix() * b.matrix(), b.inverse_matrix() * a.inverse_matrix());
}

}  // namespace penumbra
