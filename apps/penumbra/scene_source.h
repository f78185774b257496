// What the frames of one source (BatchJob::source: one file with the same options but
// for their timing) share: the loaded file, posed per frame, and, while the poses move
// nothing (a file without animation rendered over frames, or frames where it holds
// still), one accelerator.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "core/accel/accel.h"
#include "core/scene/scene.h"
#include "io/gltf/gltf_asset.h"

namespace penumbra {

struct SceneSetup;

class SceneSource {
public:
    // The loaded file; null until the first frame loads it (setup_scene).
    std::unique_ptr<GltfAsset> asset;
    // Whether a later frame will pose the file again. Else setup_scene frees it once the
    // scene is posed, before the accelerator is built, as a single load does: the parsed
    // file holds the buffers (the .bin) that only a next pose reads.
    bool more_frames = false;

    // Takes back a frame's setup once its images are done: its scene's shared parts go
    // back to the asset, and its accelerator is kept where the geometry stays in place.
    void recycle(std::unique_ptr<SceneSetup> setup);
    // The last frame's accelerator, pointed at `scene`, where `scene` (posed from asset)
    // has the geometry it was built for; else null, and it is freed.
    std::unique_ptr<Accel> reuse_accel(const Scene& scene);

private:
    std::unique_ptr<Accel> m_accel;
    std::vector<Instance> m_instances;  // the pose m_accel was built for
    size_t m_static_builds = 0;         // the asset's, when it was built
};

}  // namespace penumbra
