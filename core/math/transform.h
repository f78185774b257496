// Affine transforms as 4x4 matrices (row-major, column vectors: p' = M p) with their
// inverse kept alongside, so normals transform by the inverse transpose without
// re-inverting. Quaternions are glTF's (x, y, z, w).
#pragma once

#include <array>

#include "core/math/bounds.h"
#include "core/math/vec.h"

namespace penumbra {

struct Mat4 {
    // m[row][col]
    std::array<std::array<float, 4>, 4> m{};

    static Mat4 identity();
    // glTF stores matrices column-major: element i of the array is m[i % 4][i / 4].
    static Mat4 from_column_major(const double* v);
    float operator()(int r, int c) const { return m[r][c]; }
    float& operator()(int r, int c) { return m[r][c]; }
    Mat4 transposed() const;
    // General inverse (cofactors in double). Returns false when the matrix is singular.
    bool inverse(Mat4* out) const;
    double determinant3x3() const;
    bool is_identity() const;
};

Mat4 operator*(const Mat4& a, const Mat4& b);

struct Quat {
    float x = 0, y = 0, z = 0, w = 1;
};

class Transform {
public:
    Transform() : m_m(Mat4::identity()), m_inv(Mat4::identity()) {}
    // Throws std::invalid_argument if m is singular.
    explicit Transform(const Mat4& m);
    Transform(const Mat4& m, const Mat4& inv) : m_m(m), m_inv(inv) {}

    static Transform translate(Vec3 t);
    static Transform scale(Vec3 s);
    static Transform rotate(const Quat& q);
    // glTF's T * R * S.
    static Transform trs(Vec3 t, const Quat& r, Vec3 s);
    // Camera-style frame: the result maps local -Z to (target - eye) and +Y towards up.
    static Transform look_at(Vec3 eye, Vec3 target, Vec3 up);

    const Mat4& matrix() const { return m_m; }
    const Mat4& inverse_matrix() const { return m_inv; }
    Transform inverse() const { return Transform(m_inv, m_m); }

    Vec3 point(Vec3 p) const;
    Vec3 vector(Vec3 v) const;
    // Normals transform by the inverse transpose (correct under non-uniform scale and
    // mirroring); the result is not normalized.
    Vec3 normal(Vec3 n) const;
    Bounds3 bounds(const Bounds3& b) const;
    // True when the transform flips handedness (negative determinant): triangle winding
    // and cross-product normals flip with it.
    bool swaps_handedness() const { return m_m.determinant3x3() < 0; }

private:
    Mat4 m_m, m_inv;
};

Transform operator*(const Transform& a, const Transform& b);

}  // namespace penumbra
