#include "job/timeline.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace penumbra {

namespace {

void check_finite(const std::optional<double>& v, const char* name) {
    if (v && !std::isfinite(*v))
        throw std::invalid_argument(std::string(name) + " must be a finite number of seconds");
}

}  // namespace

ShutterInterval resolve_shutter(const TimelineSettings& s) {
    check_finite(s.time, "--time");
    check_finite(s.shutter_open, "--shutter-open");
    check_finite(s.shutter_close, "--shutter-close");
    const bool interval = s.shutter_open || s.shutter_close;
    if (interval && !(s.shutter_open && s.shutter_close))
        throw std::invalid_argument("--shutter-open and --shutter-close must be given together");
    if (s.time && interval)
        throw std::invalid_argument(
            "--time (an instant) conflicts with --shutter-open/--shutter-close (an interval)");
    if (s.frame && (s.time || interval))
        throw std::invalid_argument("--frame conflicts with --time and --shutter-open/-close");
    if (s.shutter && !s.frame)
        throw std::invalid_argument(
            "--shutter is a fraction of a frame: it needs --frame or --frames");
    if (s.shutter && !(*s.shutter >= 0 && *s.shutter <= 1))
        throw std::invalid_argument("--shutter " + std::to_string(*s.shutter) +
                                    " is not a fraction of a frame in [0, 1]");
    if (!(s.fps > 0) || !std::isfinite(s.fps))
        throw std::invalid_argument("--fps must be a positive number");
    if (s.frame && *s.frame < 0)
        throw std::invalid_argument("--frame must be >= 0");

    if (s.time) return {*s.time, *s.time};
    if (interval) {
        if (*s.shutter_close < *s.shutter_open)
            throw std::invalid_argument("--shutter-close " + std::to_string(*s.shutter_close) +
                                        " is before --shutter-open " +
                                        std::to_string(*s.shutter_open));
        return {*s.shutter_open, *s.shutter_close};
    }
    if (s.frame) {
        // The shutter opens at the frame's time and stays open for S of a frame (a
        // 180-degree shutter is S = 0.5).
        const double open = *s.frame / s.fps;
        return {open, open + s.shutter.value_or(0) / s.fps};
    }
    return {0, 0};
}

}  // namespace penumbra
