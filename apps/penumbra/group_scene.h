// The scene that consecutive images of a batch share: the views of one frame of one scene
// (BatchJob::group) render from one load and one accelerator build; only the camera
// changes between them.
#pragma once

#include <cstddef>
#include <limits>
#include <memory>
#include <string>

#include "apps/penumbra/batch.h"
#include "apps/penumbra/scene_setup.h"

namespace penumbra {

// Loaded by the first image of a group that renders (finished images are skipped without
// loading) and kept for the others. A load that failed fails the group's other images
// with its message, without loading again.
struct GroupScene {
    size_t group = std::numeric_limits<size_t>::max();
    std::unique_ptr<SceneSetup> setup;
    std::string error;
};

// The job's scene set up (loaded when the job starts a group), looking through the job's
// view. Frees the previous group's scene before loading. Throws SceneError.
SceneSetup& group_setup(const BatchJob& job, GroupScene& g);

}  // namespace penumbra
