// The scene that consecutive images of a batch share. Every image of one source (all
// frames and views of one scene of the command line or one job entry, BatchJob::source)
// renders from one loaded file: parsed and its images decoded once, posed at each frame's
// shutter. The views of one frame (BatchJob::group) also share the pose and its
// accelerator build; only the camera changes between them.
#pragma once

#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "apps/penumbra/batch.h"
#include "apps/penumbra/scene_setup.h"

namespace penumbra {

// Loaded by the first image of a source (and set up by the first of a group) that
// renders: finished images are skipped without loading. A load that failed fails the
// source's other images with its message, and a set-up that failed the group's, without
// trying again.
struct GroupScene {
    size_t source = std::numeric_limits<size_t>::max();
    SceneSource loaded;  // the source's file and its last frame's accelerator
    std::string source_error;
    bool more_frames = false;  // more_frames() of the job being rendered, set by the batch
    size_t group = std::numeric_limits<size_t>::max();
    std::unique_ptr<SceneSetup> setup;
    std::string error;
};

// The job's scene set up (posed when the job starts a group, loaded when it starts a
// source), looking through the job's view. Ends the previous group and source first.
// Throws SceneError.
SceneSetup& group_setup(const BatchJob& job, GroupScene& g);

// Whether a later group of jobs[i]'s source follows it in the batch: its file is then kept
// for that group's frame (SceneSource::more_frames).
bool more_frames(const std::vector<BatchJob>& jobs, size_t i);

// After the last image of a group: frees its set-up, handing what the next frame may share
// back to the source; with `source_done`, frees the loaded file too.
void end_group(GroupScene& g, bool source_done);

}  // namespace penumbra
