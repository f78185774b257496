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
    Transform() : m_m(Mat4::identity()), m_inv(Mat4::identity()) { classify(); }
    // Throws std::invalid_argument if m is singular.
    explicit Transform(const Mat4& m);
    Transform(const Mat4& m, const Mat4& inv) : m_m(m), m_inv(inv) { classify(); }

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

    // Inline, with a shortcut for pure translations (most glTF instances, and every
    // identity): they are on the path of every hit. The shortcut gives the general
    // formula's values, whose 0 * x and 1 * x terms are exact in IEEE arithmetic
    // (except that the sign of a zero coordinate may differ).
    // The general case inline too: as a call, GCC packs p.x and p.y into one register
    // through the stack at every call site, even on the translation path, and an 8-byte
    // load of two 4-byte stores waits for both to reach memory; inline, p stays in registers.
    Vec3 point(Vec3 p) const {
        const auto& m = m_m.m;
        if (m_translation_only) return {p.x + m[0][3], p.y + m[1][3], p.z + m[2][3]};
        const Vec3 r{m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
                     m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
                     m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
        const float w = m[3][0] * p.x + m[3][1] * p.y + m[3][2] * p.z + m[3][3];
        return w == 1.0f ? r : r / w;
    }
    Vec3 vector(Vec3 v) const {
        if (m_translation_only) return v;
        const auto& m = m_m.m;
        return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
                m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
                m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
    }
    // Normals transform by the inverse transpose (correct under non-uniform scale and
    // mirroring); the result is not normalized.
    Vec3 normal(Vec3 n) const {
        if (m_translation_only) return n;
        const auto& mi = m_inv.m;  // (M^-1)^T n: use the columns of the inverse
        return {mi[0][0] * n.x + mi[1][0] * n.y + mi[2][0] * n.z,
                mi[0][1] * n.x + mi[1][1] * n.y + mi[2][1] * n.z,
                mi[0][2] * n.x + mi[1][2] * n.y + mi[2][2] * n.z};
    }
    Bounds3 bounds(const Bounds3& b) const;
    // True when the transform flips handedness (negative determinant): triangle winding
    // and cross-product normals flip with it.
    bool swaps_handedness() const { return m_swaps_handedness; }
    // True when the matrix and its inverse are translations (identity included): the
    // linear part is exactly the identity and the last row (0, 0, 0, 1).
    bool is_translation_only() const { return m_translation_only; }
    // True when the last row is (0, 0, 0, 1): point() divides by no w (it is exactly 1 at
    // every finite point).
    bool is_affine() const { return m_affine; }
    // Column c of the matrix's top three rows, with a fourth float 0: 16-byte aligned, for
    // the hot path's four-lane arithmetic (F4::load), where lane r of c0 * x + c1 * y +
    // c2 * z + c3 is point()'s row r, in the same order; column 3 is the translation.
    const float* column(int c) const { return m_columns[c]; }

private:
    // Sets the flags above from the matrices (every constructor calls it; the matrices
    // never change afterwards).
    void classify();

    Mat4 m_m, m_inv;
    alignas(16) float m_columns[4][4];
    bool m_translation_only = true;
    bool m_affine = true;
    bool m_swaps_handedness = false;
};

Transform operator*(const Transform& a, const Transform& b);

}  // namespace penumbra
