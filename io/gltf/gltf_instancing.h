// EXT_mesh_gpu_instancing: a node whose mesh is drawn many times, each with its own
// translation, rotation and scale from accessors, becomes that many Instances of the one
// shared Object (nothing about the mesh is duplicated).
#pragma once

#include <string>
#include <vector>

#include "core/scene/scene.h"
#include "io/gltf/gltf_context.h"

namespace penumbra {

// True when the node carries the extension: its instances of Scene::objects[object] (the
// node's mesh, or its morphed copy) were appended to scene.instances (the node's world
// transform times each instance's TRS). A node that moves (`motion`: its world
// transforms at the shutter's time steps, empty if still) moves its instances with it.
bool add_gpu_instances(const GltfContext& ctx, const std::string& el, const tinygltf::Node& node,
                       int node_index, uint32_t object, const Transform& world,
                       const std::vector<Transform>& motion, Scene& scene);

}  // namespace penumbra
