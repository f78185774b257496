#include "apps/penumbra/timeline_options.h"

namespace penumbra {

void add_timeline_options(CLI::App* cmd, TimelineSettings& t, bool with_frames) {
    // Callbacks rather than bound variables: "not given" must stay distinguishable from
    // 0, so that conflicting options are reported instead of one silently winning.
    cmd->add_option_function<double>(
        "--time", [&t](double v) { t.time = v; },
        "Render the animation at this instant, in seconds: no motion blur (default 0)");
    cmd->add_option_function<double>(
        "--shutter-open", [&t](double v) { t.shutter_open = v; },
        "Motion blur: the exposure opens at this animation time, in seconds (with "
        "--shutter-close)");
    cmd->add_option_function<double>(
        "--shutter-close", [&t](double v) { t.shutter_close = v; },
        "Motion blur: the exposure closes at this animation time, in seconds");
    cmd->add_option_function<int>(
           "--frame", [&t](int v) { t.frame = v; },
           "Render frame N: the shutter opens at N / fps")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--fps", t.fps,
                    with_frames ? "Frames per second for --frame and --frames"
                                : "Frames per second for --frame")
        ->capture_default_str()
        ->check(CLI::PositiveNumber);
    cmd->add_option_function<double>(
           "--shutter", [&t](double v) { t.shutter = v; },
           with_frames ? "Motion blur with --frame/--frames: the shutter stays open this "
                         "fraction of a frame (0.5: a 180-degree shutter)"
                       : "Motion blur with --frame: the shutter stays open this fraction of "
                         "a frame (0.5: a 180-degree shutter)")
        ->check(CLI::Range(0.0, 1.0));
}

}  // namespace penumbra
