// `penumbra render`: options, the per-image pipeline (set up, render in passes, write)
// and the batch around it (scenes x frames or a job file, resume, summary table).
#pragma once

#include <string>
#include <vector>

#include "job/render_options.h"

namespace CLI {
class App;  // CLI/CLI.hpp, which only the .cpp files that build commands include
}

namespace penumbra {

void add_render_command(CLI::App& app, RenderCommandOptions& options);
// Renders every image of the batch; one failing scene does not stop the others. Returns
// the exit status: 0 when all rendered or were skipped, 1 if any failed, 130 after
// Ctrl-C.
int run_render_command(const RenderCommandOptions& options);

struct BatchJob;
struct JobResult;
// Renders the given jobs of a batch (as run_render_command does after planning it) and
// returns the exit status: 0, 1 if any failed, 128 + the signal after an interrupt.
int run_render_jobs(const std::vector<BatchJob>& jobs, const RenderCommandOptions& options,
                    std::vector<JobResult>& results);

}  // namespace penumbra
