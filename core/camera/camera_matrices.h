// A camera's view and projection as 4x4 matrices in the conventions of OpenEXR's
// worldToCamera and worldToNDC attributes (RenderMan's), so that compositing tools can
// reproject pixels; the matrices are penumbra's column-vector ones (p' = M p).
#pragma once

#include "core/math/transform.h"
#include "core/scene/scene.h"

namespace penumbra {

// World to a left-handed camera space: +X right, +Y up, +Z the viewing direction
// (glTF's camera space with Z negated).
Mat4 world_to_camera_lh(const CameraDesc& desc);

// World to normalized device coordinates of a width x height image: x to the right and y
// down, (0,0) the top-left and (1,1) the bottom-right corner, after dividing by w. z is
// 0 at znear and 1 at zfar (perspective: 1 at infinity when zfar is 0; orthographic:
// the distance itself then). Matches make_camera: the vertical extent is kept and the
// horizontal one follows the image's aspect.
Mat4 world_to_ndc(const CameraDesc& desc, int width, int height);

}  // namespace penumbra
