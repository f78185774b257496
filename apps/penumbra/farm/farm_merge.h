// The farm's last step: once every array task ended, assemble each banded image from its
// band files (job/band_merge.h), collect every image's result from the task records, and
// write the batch summary (JOB.farm/summary.txt) that `farm submit --wait` prints.
#pragma once

#include <string>

namespace penumbra {

// Returns 0 when every image is done or skipped, 1 when any failed (a broken scene, a
// task that left no record) or is partial.
int run_farm_merge(const std::string& job_file, double checkpoint_interval);

}  // namespace penumbra
