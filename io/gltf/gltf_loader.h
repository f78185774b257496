// glTF 2.0 (.gltf and .glb) to Scene. Every input is validated; problems throw
// SceneError with the file name, the glTF element path and what was expected, e.g.
// "scene.gltf: meshes[3].primitives[0]: POSITION accessor has 0 elements".
#pragma once

#include <string>

#include "core/lights/light_units.h"
#include "core/math/mat3.h"
#include "core/scene/scene.h"
#include "io/image/image_reader.h"

namespace penumbra {

struct GltfLoadOptions {
    int scene = -1;  // glTF scene index; -1: the file's default scene (or scene 0)
    // glTF's linear Rec.709 colours (factors, colour textures, vertex and light colours)
    // into the working space (io/color/scene_color.h); identity: left as they are.
    Mat3 rec709_to_working = Mat3::identity();
    // The exposure interval in the file's animation seconds (Scene::shutter_open/close).
    // Nodes are posed at shutter_open; what moves before shutter_close gets time steps.
    // Equal values are a still at that time; both 0 (the default) is the file's pose at
    // time 0, which for a file without animations is its nodes' own transforms.
    double shutter_open = 0, shutter_close = 0;
    // Motion vectors: when > 0, the scene is also posed this many seconds (a frame's
    // duration) before and after shutter_open, into Scene::frame_neighbours; 0 leaves it
    // empty and costs nothing.
    double neighbour_frame_offset = 0;
    // KHR_materials_variants: the variant whose materials primitives use where they map
    // one; empty: every primitive's default material. An unknown name is a SceneError.
    std::string variant = "";
    // KHR_lights_punctual intensities: photometric (cd, lux; the spec's) or radiometric.
    LightUnits light_units = LightUnits::Photometric;
    // Every warning (an undecodable image, data out of spec) is a SceneError instead.
    bool strict = false;
    // Images whose header claims more pixels are refused (undecodable) before decoding.
    uint64_t max_texture_pixels = kDefaultMaxTexturePixels;
};

// Where load_gltf's time goes, for big scenes (docs/performance.md, "Big scenes"): wall
// seconds, and CPU seconds of the whole process (all threads), which a busy machine
// inflates less.
struct GltfLoadStats {
    struct Stage {
        double seconds = 0, cpu_seconds = 0;
    };
    Stage parse;      // the file and its buffers read, JSON parsed, decompressed
    Stage meshes;     // accessors to TriangleMeshes, with their checks
    Stage materials;  // materials, with their texture images decoded
    Stage nodes;      // animations, the node tree, instances, deformation
    // The file was parsed for this scene (GltfAsset::scene_at: else it posed a file parsed
    // before, with parse zero).
    bool parsed = false;
};

// Loads the file at path; throws SceneError for bad input, including a shutter that
// closes before it opens. Cameras and lights are only those the file defines; the
// caller adds defaults (see camera/default_camera.h). `stats`, when given, receives the
// time each stage took.
Scene load_gltf(const std::string& path, const GltfLoadOptions& options = {},
                GltfLoadStats* stats = nullptr);

}  // namespace penumbra
