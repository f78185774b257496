// The timeline options shared by `render`, `check-accel` and job files: an instant
// (--time T), an exposure interval (--shutter-open A --shutter-close B) or a frame
// (--frame N --fps F --shutter S), resolved to the shutter interval in animation seconds.
#pragma once

#include <optional>

namespace penumbra {

struct TimelineSettings {
    std::optional<double> time;                         // an instant: no blur
    std::optional<double> shutter_open, shutter_close;  // seconds
    std::optional<int> frame;                           // opens at frame / fps
    std::optional<double> shutter;  // with a frame: open for this fraction of a frame
    double fps = 24;
};

struct ShutterInterval {
    double open = 0, close = 0;  // equal for a still
};

// Unset: time 0, no blur. Throws std::invalid_argument naming the options for
// conflicting (an instant and an interval, a frame and a time) or invalid values
// (non-finite, closing before opening, a shutter fraction outside [0, 1] or without a
// frame, fps <= 0).
ShutterInterval resolve_shutter(const TimelineSettings& s);

}  // namespace penumbra
