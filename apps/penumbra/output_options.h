// The `render` options for colour management and EXR output (OCIO config, working and
// output spaces, preview display/view/look, AOVs, half, compression, reference,
// timing), kept apart from the batch and image options.
#pragma once

#include <CLI/CLI.hpp>

#include "apps/penumbra/render_command.h"

namespace penumbra {

void add_output_options(CLI::App* cmd, RenderCommandOptions& o);

}  // namespace penumbra
