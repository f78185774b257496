// Motion vectors (Aov::Vector), as Cycles' Vector pass (kernel primitive_motion_vector):
// the point of a surface a camera sample hit, mapped to raster pixels by the camera at the
// frame, and the same point of the same surface (same instance, triangle and
// barycentrics, so skinned and morphed vertices carry it along) one frame before and one
// frame after, each mapped by that frame's camera (Scene::frame_neighbours).
#pragma once

#include "core/math/transform.h"
#include "core/ray.h"
#include "core/scene/scene.h"

namespace penumbra {

// World to raster, as homogeneous 4x4 matrices, of the camera at the frame and at the
// frames before and after. Raster is Cycles': pixels from the image's bottom-left corner,
// x to the right and y up (penumbra's own raster has y down).
struct MotionVectorCameras {
    Mat4 current, previous, next;
};

// The render camera `camera` (a file camera, a view or the automatic one) for a
// width x height image; previous and next: the same camera at those frames, nullptr for
// one that does not move (views and the automatic camera). Lens shifts do not change
// where a point lands, so a thin lens maps like its pinhole.
MotionVectorCameras motion_vector_cameras(const CameraDesc& camera, const CameraDesc* previous,
                                          const CameraDesc* next, int width, int height);

// The hit's vector: (previous - current, current - next) in raster pixels, Cycles' Vector
// pass's X, Y (to the previous frame) and Z, W (from the next frame); for a point moving
// right by v pixels a frame, (-v, 0, -v, 0). The point at the frame is the hit's object-
// space point at shutter open (a motion-blurred sample's vector is that of the frame, not
// of its own time). 0 without frame neighbours (a scene loaded without them), and where a
// point lies in a camera's plane or the arithmetic overflows.
Vec4 motion_vector(const Scene& scene, const MotionVectorCameras& cameras, const Hit& hit);

}  // namespace penumbra
