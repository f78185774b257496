// A glTF file loaded once for many images (the frames of an animation): the parsed file and
// what no animation changes (meshes, materials, decoded texture images) are kept, and
// scene_at() poses the file at each shutter, evaluating only the animation again.
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "core/scene/scene.h"
#include "io/gltf/gltf_loader.h"

namespace penumbra {

struct GltfAssetState;  // the parsed file and the kept parts (gltf_asset.cpp)

class GltfAsset {
public:
    // Reads, parses and checks the file (its asset version, extensions and variant);
    // `options`' shutter is not used: each scene_at names its own. Throws SceneError.
    GltfAsset(const std::string& path, const GltfLoadOptions& options);
    ~GltfAsset();
    GltfAsset(const GltfAsset&) = delete;
    GltfAsset& operator=(const GltfAsset&) = delete;

    // The file posed over [shutter_open, shutter_close] animation seconds, the same Scene
    // as load_gltf with that shutter gives. Meshes, materials and images come from the
    // last recycled scene where they can (a file without animated materials); otherwise
    // they are read from the parsed file. `stats` receives the time of each stage this
    // scene cost: zero for the parts reused, the parse only for the first after it. Throws
    // SceneError for a bad shutter or bad data.
    Scene scene_at(double shutter_open, double shutter_close, GltfLoadStats* stats = nullptr);
    // Takes back a scene that scene_at returned, once nothing refers to it any more, and
    // keeps the parts that every pose shares for the next scene_at; drops the rest.
    void recycle(Scene&& scene);

    // Whether recycling `scene` keeps every mesh array it has where it is: nothing in it
    // deforms and its meshes are the shared ones, kept between poses (no material is
    // animated). An accelerator built over it then serves the next pose with the same
    // instances (Accel::rebind), as long as static_builds() stays the same.
    bool keeps_geometry(const Scene& scene) const;

    // How often the file was parsed (1 while its scenes are recycled) and the shared
    // parts built (meshes read, images decoded): for tests and logs.
    size_t parses() const;
    size_t static_builds() const;

private:
    std::unique_ptr<GltfAssetState> m;
};

}  // namespace penumbra
