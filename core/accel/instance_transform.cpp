#include "core/accel/instance_transform.h"

namespace penumbra {

WorldToObject world_to_object(const Mat4& m) {
    WorldToObject w;
    auto& out = w.m;
    double a[3][3];
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) a[r][c] = m(r, c);
    const double c00 = a[1][1] * a[2][2] - a[1][2] * a[2][1];
    const double c01 = a[1][2] * a[2][0] - a[1][0] * a[2][2];
    const double c02 = a[1][0] * a[2][1] - a[1][1] * a[2][0];
    const double det = a[0][0] * c00 + a[0][1] * c01 + a[0][2] * c02;
    const double s = 1.0 / det;
    out[0][0] = c00 * s;
    out[1][0] = c01 * s;
    out[2][0] = c02 * s;
    out[0][1] = (a[0][2] * a[2][1] - a[0][1] * a[2][2]) * s;
    out[1][1] = (a[0][0] * a[2][2] - a[0][2] * a[2][0]) * s;
    out[2][1] = (a[0][1] * a[2][0] - a[0][0] * a[2][1]) * s;
    out[0][2] = (a[0][1] * a[1][2] - a[0][2] * a[1][1]) * s;
    out[1][2] = (a[0][2] * a[1][0] - a[0][0] * a[1][2]) * s;
    out[2][2] = (a[0][0] * a[1][1] - a[0][1] * a[1][0]) * s;
    for (int r = 0; r < 3; ++r)
        out[r][3] = -(out[r][0] * m(0, 3) + out[r][1] * m(1, 3) + out[r][2] * m(2, 3));
    return w;
}

Ray moving_object_ray(const std::vector<QuatDecomposition>& steps, const Ray& ray) {
    return transform_ray(world_to_object(motion_matrix_at(steps, ray.time)), ray);
}

}  // namespace penumbra
