// The options that decide how many samples each pixel takes, which are clamped and what
// becomes of them: adaptive sampling to an error target, firefly control (clamps,
// regularization) and denoising. Part of the image options, so `converge`
// configurations can compare them.
#pragma once

#include <CLI/CLI.hpp>

#include "apps/penumbra/render_command.h"
#include "io/image/image_writer.h"

namespace penumbra {

void add_sampling_options(CLI::App* cmd, RenderCommandOptions& o);

// The header fields of the options that are on (none when all are off, so a render
// without them writes no field for them).
Metadata sampling_metadata(const RenderCommandOptions& o);

}  // namespace penumbra
