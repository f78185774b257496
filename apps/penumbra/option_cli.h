// The command line of the declared render options (job/option_table.h).
#pragma once

#include <functional>

#include <CLI/CLI.hpp>

#include "job/option_table.h"

namespace penumbra {

// Adds every declared option that `wanted` accepts to cmd, setting o when parsed. The
// help shows each option's default as o holds it now.
void add_declared_options(CLI::App* cmd, RenderCommandOptions& o,
                          const std::function<bool(const OptionDecl&)>& wanted);

// The image options (render and converge's --config).
bool is_image_option(const OptionDecl& d);
// Every option of `penumbra render` (all but the farm's job-file keys).
bool is_render_option(const OptionDecl& d);
// The animation time or interval of an image: --time, --shutter-open, --shutter-close,
// --frame, --fps, --shutter.
bool is_timeline_option(const OptionDecl& d);

}  // namespace penumbra
