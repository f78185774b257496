// transforms.json, the camera file of NeRF datasets as instant-ngp and nerfstudio read it,
// written beside a multi-view batch's images: the intrinsics (camera_angle_x, w, h, fl_x,
// fl_y, cx, cy) and per frame the image's file_path and its camera-to-world
// transform_matrix in OpenGL camera axes (the camera looks down -Z, +Y up).
#pragma once

#include <string>
#include <vector>

#include "core/math/transform.h"

namespace penumbra {

// A pinhole camera's intrinsics in pixels; the principal point is the image centre, and
// pixel (i, j) spans [i, i + 1) x [j, j + 1), so its centre is at i + 0.5 (nerfstudio's
// convention).
struct Intrinsics {
    int w = 0, h = 0;
    double fl_x = 0, fl_y = 0, cx = 0, cy = 0;
    bool operator==(const Intrinsics& o) const {
        return w == o.w && h == o.h && fl_x == o.fl_x && fl_y == o.fl_y && cx == o.cx && cy == o.cy;
    }
};

// A perspective camera of vertical field of view yfov (radians) on a w x h image, as
// make_camera builds it: square pixels, the vertical extent kept.
Intrinsics perspective_intrinsics(int w, int h, float yfov);

struct TransformsFrame {
    std::string file_path;  // relative to the folder of transforms.json
    Mat4 transform_matrix;  // camera to world, rows
    Intrinsics intrinsics;
};

// The file's text: the intrinsics at the top level when every frame shares them, else in
// each frame (both programs read per-frame intrinsics).
std::string transforms_json_text(const std::vector<TransformsFrame>& frames);

// The frames of an existing transforms.json; empty when there is none or it cannot be
// read as one.
std::vector<TransformsFrame> read_transforms_json(const std::string& path);

// Writes path (atomically) with the frames it already lists, those of the same file_path
// replaced by `frames`, and the others of `frames` appended in order. Processes updating
// one file (farm tasks) take turns: the folder is locked (flock) meanwhile.
void update_transforms_json(const std::string& path, const std::vector<TransformsFrame>& frames);

}  // namespace penumbra
