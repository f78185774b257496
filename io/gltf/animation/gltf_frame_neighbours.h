// Internal to io/: the scene at the frames before and after the rendered one, for motion
// vectors (Scene::frame_neighbours). The loader starts it before the node tree, whose
// cameras and deformed meshes add theirs as they are made; the instances follow here.
#pragma once

#include "core/scene/scene.h"
#include "io/gltf/animation/gltf_node_motion.h"
#include "io/gltf/gltf_context.h"

namespace penumbra {

// Empty neighbours at shutter open -/+ `offset` seconds (a frame's duration), or nothing
// for offset 0. Throws SceneError for a negative or non-finite offset.
void start_frame_neighbours(const GltfContext& ctx, const Shutter& shutter, double offset,
                            Scene& scene);

// Every instance's object-to-world matrix at the neighbouring frames where any instance
// moves (none kept otherwise); after load_nodes.
void finish_frame_neighbours(const GltfContext& ctx, const NodeMotion& motion, Scene& scene);

}  // namespace penumbra
