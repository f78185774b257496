// The timeline options of `render` and `check-accel`: --time, --shutter-open and
// --shutter-close, --frame, --fps and --shutter (resolved by job/timeline.h).
#pragma once

#include <CLI/CLI.hpp>

#include "job/timeline.h"

namespace penumbra {

// `with_frames`: the command also has --frames, which --shutter applies to.
void add_timeline_options(CLI::App* cmd, TimelineSettings& t, bool with_frames);

}  // namespace penumbra
