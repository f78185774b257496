// One glTF file to one Scene: a GltfAsset (gltf_asset.h) posed once.
#include "io/gltf/gltf_loader.h"

#include "io/gltf/gltf_asset.h"

namespace penumbra {

Scene load_gltf(const std::string& path, const GltfLoadOptions& options, GltfLoadStats* stats) {
    GltfAsset asset(path, options);
    return asset.scene_at(options.shutter_open, options.shutter_close, stats);
}

}  // namespace penumbra
