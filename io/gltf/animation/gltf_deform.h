// Internal to io/: deformation. A node whose mesh is skinned, or has morph targets with
// nonzero or animated weights, gets its own copy of the mesh, deformed at shutter open
// and, when it changes within the shutter, at each time step (TriangleMesh's
// motion_positions and motion_normals), and for motion vectors at the neighbouring frames
// (Scene::frame_neighbours).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "io/gltf/gltf_context.h"
#include "io/gltf/animation/gltf_node_motion.h"

namespace penumbra {

struct DeformedObject {
    uint32_t object;  // the node's own Object in Scene::objects
    // A skinned mesh's vertices are in world space (glTF 2.0, section 3.7.3.3: the skinned
    // node's own transform is ignored): its instance takes the identity.
    bool world_space;
};

// Empty when the node's mesh does not deform (it then shares Scene::objects[node.mesh]).
// Throws SceneError for an invalid skin, morph target or weight list.
std::optional<DeformedObject> add_deformed_object(const GltfContext& ctx,
                                                  const NodeMotion& motion, int node_index,
                                                  const std::vector<MeshOrigin>& origins,
                                                  Scene& scene);

}  // namespace penumbra
