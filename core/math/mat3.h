// 3x3 matrices for linear colour transforms (RGB to RGB or XYZ): row-major, column
// vectors (c' = M c). Products and inverses are computed in double.
#pragma once

#include <array>
#include <cmath>

#include "core/math/vec.h"

namespace penumbra {

struct Mat3 {
    // m[row][col]
    std::array<std::array<double, 3>, 3> m{};

    static Mat3 identity() {
        Mat3 r;
        for (int i = 0; i < 3; ++i) r.m[i][i] = 1;
        return r;
    }
    // Columns are the images of the unit vectors: what a colour transform makes of pure
    // red, green and blue.
    static Mat3 from_columns(Vec3 c0, Vec3 c1, Vec3 c2) {
        Mat3 r;
        for (int i = 0; i < 3; ++i) {
            r.m[i][0] = c0[i];
            r.m[i][1] = c1[i];
            r.m[i][2] = c2[i];
        }
        return r;
    }
    Vec3 operator*(Vec3 v) const {
        Vec3 r;
        for (int i = 0; i < 3; ++i) r[i] = float(m[i][0] * v.x + m[i][1] * v.y + m[i][2] * v.z);
        return r;
    }
    Mat3 operator*(const Mat3& b) const {
        Mat3 r;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                r.m[i][j] = m[i][0] * b.m[0][j] + m[i][1] * b.m[1][j] + m[i][2] * b.m[2][j];
        return r;
    }
    double determinant() const {
        return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
               m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    }
    // Cofactor inverse; false when singular.
    bool inverse(Mat3* out) const {
        const double det = determinant();
        if (!(std::abs(det) > 1e-12)) return false;
        Mat3 r;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                const int a = (j + 1) % 3, b = (j + 2) % 3, c = (i + 1) % 3, d = (i + 2) % 3;
                r.m[i][j] = (m[a][c] * m[b][d] - m[a][d] * m[b][c]) / det;
            }
        *out = r;
        return true;
    }
    // Largest absolute difference of corresponding elements.
    double max_difference(const Mat3& b) const {
        double d = 0;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) d = std::max(d, std::abs(m[i][j] - b.m[i][j]));
        return d;
    }
    bool is_identity() const { return max_difference(identity()) == 0; }
};

}  // namespace penumbra
