// The options that decide what an image looks like (size, samples, camera, integrator,
// sampler, lights, lens), for `render`, `converge` and converge's --config strings.
#pragma once

#include <CLI/CLI.hpp>

#include "apps/penumbra/render_command.h"

namespace penumbra {

void add_image_options(CLI::App* cmd, RenderCommandOptions& o);

}  // namespace penumbra
