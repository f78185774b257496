#include "core/camera/camera_matrices.h"

#include <cmath>

namespace penumbra {

Mat4 world_to_camera_lh(const CameraDesc& desc) {
    Mat4 flip = Mat4::identity();
    flip(2, 2) = -1;
    return flip * desc.to_world.inverse_matrix();
}

Mat4 world_to_ndc(const CameraDesc& desc, int width, int height) {
    const float aspect = float(width) / float(height);
    const float n = desc.znear, f = desc.zfar;
    Mat4 p;  // left-handed camera space to homogeneous NDC
    if (desc.type == ProjectionType::Orthographic) {
        const float ymag = desc.ymag, xmag = desc.ymag * aspect;
        p(0, 0) = 0.5f / xmag;
        p(0, 3) = 0.5f;
        p(1, 1) = -0.5f / ymag;
        p(1, 3) = 0.5f;
        p(2, 2) = f > n ? 1 / (f - n) : 1;
        p(2, 3) = f > n ? -n / (f - n) : 0;
        p(3, 3) = 1;
    } else {
        // x_ndc = 0.5 + 0.5 x / (z tan(fov_x / 2)), and likewise y (flipped), over w = z.
        const float tan_y = std::tan(0.5f * desc.yfov), tan_x = tan_y * aspect;
        p(0, 0) = 0.5f / tan_x;
        p(0, 2) = 0.5f;
        p(1, 1) = -0.5f / tan_y;
        p(1, 2) = 0.5f;
        p(2, 2) = f > n ? f / (f - n) : 1;
        p(2, 3) = f > n ? -f * n / (f - n) : -n;
        p(3, 2) = 1;
    }
    return p * world_to_camera_lh(desc);
}

}  // namespace penumbra
