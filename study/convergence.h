// How an image's error falls with samples and time: the least-squares slope of
// log(error) against log(spp) (about -1 for Monte Carlo), and the time to reach a target
// error. The error itself: core/film/image_error.h.
#pragma once

#include <optional>
#include <vector>

namespace penumbra {

// Least-squares slope of log(y) against log(x); needs two distinct positive x and
// positive y (points with y <= 0 are ignored). std::nullopt when undetermined.
std::optional<double> log_log_slope(const std::vector<double>& x, const std::vector<double>& y);

struct TimeToError {
    double seconds = 0;
    bool extrapolated = false;  // beyond the measured points, along the fitted power law
    bool at_most = false;       // the first point was already there: no later than this
};

// When the error first reaches `target`, from measured (time, error) points in time
// order: the first point's time if it is already there, else linear interpolation in
// log-log between the point before and the first point at or below the target. Not
// reached: extrapolated along the least-squares power law through all points.
// std::nullopt when that does not fall (or there are no points).
std::optional<TimeToError> time_to_error(const std::vector<double>& seconds,
                                         const std::vector<double>& error, double target);

}  // namespace penumbra
