// Internal to io/: what the glTF loader's parts share while turning one parsed
// tinygltf::Model into a Scene: the model, the file name for messages, and the helpers
// that validate references and format "<file>: <element>: <problem>" errors.
#pragma once

#include <tiny_gltf.h>

#include <functional>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/lights/light_units.h"
#include "core/math/mat3.h"
#include "core/scene/scene.h"

namespace penumbra {

struct GltfContext {
    const tinygltf::Model& model;
    std::string file;  // as the caller named it; prefixes every message
    Mat3 rec709_to_working = Mat3::identity();  // for light colours (scene_color.h)
    LightUnits light_units = LightUnits::Photometric;  // KHR_lights_punctual intensities
    int variant = -1;  // KHR_materials_variants index chosen; -1: default materials
    bool strict = false;  // warn() and warn_once() throw, as fail() does (--strict)
    bool silent = false;  // warn() and warn_once() do nothing (a dry run's context)
    uint64_t max_texture_pixels = uint64_t(1) << 28;  // GltfLoadOptions::max_texture_pixels

    // Throws SceneError "<file>: <element>: <problem>".
    [[noreturn]] void fail(const std::string& element, const std::string& problem) const {
        throw SceneError(file + ": " + element + ": " + problem);
    }
    // Logs "<file>: <element>: <problem>" (warn_once: once per process and message); in
    // strict mode, throws it as fail() does.
    void warn(const std::string& element, const std::string& problem) const;
    void warn_once(const std::string& element, const std::string& problem) const;

    // Checks that `index` refers to one of `count` items of the kind `what` (e.g.
    // "material"), referenced from `element`; throws naming both otherwise.
    void check_index(const std::string& element, const char* what, int index, size_t count,
                     const char* plural) const {
        if (index < 0 || size_t(index) >= count)
            fail(element, std::string(what) + " index " + std::to_string(index) +
                              " out of range (" + std::to_string(count) + " " + plural + ")");
    }
};

// "name[i]", the glTF element path of array entry i.
inline std::string element(const char* array, size_t i) {
    return std::string(array) + "[" + std::to_string(i) + "]";
}

// " (nodes[1] rotation, nodes[2] scale, ...)": up to three examples, for the summary
// warnings that stand for many elements of one kind.
inline std::string examples(const std::vector<std::string>& items) {
    std::string s = " (";
    for (size_t i = 0; i < items.size() && i < 3; ++i) s += (i ? ", " : "") + items[i];
    return s + (items.size() > 3 ? ", ...)" : ")");
}

// Where a Scene::meshes entry came from: its glTF mesh and primitive and, when its
// vertices were split per triangle for flat shading (and skins or morph targets need the
// file's vertices), the file vertex of each of its vertices.
struct MeshOrigin {
    int mesh = -1, primitive = -1;
    std::vector<uint32_t> source_vertex;  // empty: vertex i is the file's vertex i
};

class MeshChecks;

// Each glTF mesh becomes Scene::objects[i] (same index), with one TriangleMesh per
// triangle primitive appended to Scene::meshes (gltf_mesh.cpp), and its origin to
// `origins` (same index). Out-of-spec data is counted in `checks` (gltf_mesh_checks.h).
void load_meshes(const GltfContext& ctx, Scene& scene, std::vector<MeshOrigin>& origins,
                 MeshChecks& checks);

class GltfAnimations;
struct Shutter;

// Materials, and the textures and images they use, decoded with OIIO
// (gltf_material.cpp). Only images that a material references are decoded. Materials
// animated through KHR_animation_pointer take their values at shutter open, with time
// steps where they change within the shutter (Scene::material_steps). `animations` is
// called once the file's own materials are read, so that their messages come before the
// animations' (which it parses).
void load_materials(const GltfContext& ctx, const std::function<const GltfAnimations&()>& animations,
                    const Shutter& shutter, Scene& scene);

class NodeMotion;

// Instances, cameras and lights of glTF scene `scene_index` (gltf_nodes.cpp), posed at
// shutter open, with time steps for what moves within the shutter (`motion`); needs the
// objects from load_meshes.
void load_nodes(const GltfContext& ctx, int scene_index, const NodeMotion& motion,
                const std::vector<MeshOrigin>& origins, Scene& scene);

}  // namespace penumbra
