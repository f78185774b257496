// transforms.json for a group of views (the views of one frame of one scene): each folder
// the group's images went to gets the cameras of the images written there, in the NeRF
// convention (job/transforms_json.h).
#pragma once

#include <cstddef>
#include <vector>

#include "apps/penumbra/batch.h"
#include "apps/penumbra/scene_setup.h"

namespace penumbra {

// jobs[i] gave results[first_result + i] (the jobs after the last result are to come). Writes the
// cameras of group `group`'s view images that exist (rendered now, partial, or finished by an
// earlier run), pointing at the PNG preview when there is one, else at the EXR. Farm bands write
// none (the merge assembles their images). A file that cannot be written is a warning: the images
// are there.
void write_view_transforms(const std::vector<BatchJob>& jobs, const std::vector<JobResult>& results,
                           size_t first_result, size_t group, const SceneSetup& setup);

}  // namespace penumbra
