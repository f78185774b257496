#include "study/convergence.h"

#include <algorithm>
#include <cmath>

namespace penumbra {

namespace {

struct LogLogFit {
    double slope = 0, intercept = 0;
};

std::optional<LogLogFit> fit_log_log(const std::vector<double>& x, const std::vector<double>& y) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int n = 0;
    for (size_t i = 0; i < x.size() && i < y.size(); ++i) {
        if (!(x[i] > 0) || !(y[i] > 0) || !std::isfinite(x[i]) || !std::isfinite(y[i]))
            continue;
        const double lx = std::log(x[i]), ly = std::log(y[i]);
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
        ++n;
    }
    const double denom = n * sxx - sx * sx;
    if (n < 2 || !(denom > 1e-12 * std::max(1.0, n * sxx))) return std::nullopt;
    const double slope = (n * sxy - sx * sy) / denom;
    return LogLogFit{slope, (sy - slope * sx) / n};
}

}  // namespace

std::optional<double> log_log_slope(const std::vector<double>& x, const std::vector<double>& y) {
    const std::optional<LogLogFit> fit = fit_log_log(x, y);
    return fit ? std::optional<double>(fit->slope) : std::nullopt;
}

std::optional<TimeToError> time_to_error(const std::vector<double>& seconds,
                                         const std::vector<double>& error, double target) {
    const size_t n = std::min(seconds.size(), error.size());
    if (n == 0 || !(target > 0)) return std::nullopt;
    for (size_t i = 0; i < n; ++i) {
        if (!(error[i] <= target)) continue;
        if (i == 0) return TimeToError{seconds[0], false, true};
        // Error and time both follow power laws, so interpolate linearly in log-log.
        const double t0 = std::log(seconds[i - 1]), t1 = std::log(seconds[i]);
        const double e0 = std::log(error[i - 1]), e1 = std::log(error[i]);
        if (!std::isfinite(t0 + t1 + e0 + e1) || !(e1 < e0))
            return TimeToError{seconds[i], false, false};
        return TimeToError{std::exp(t0 + (std::log(target) - e0) / (e1 - e0) * (t1 - t0)),
                           false, false};
    }
    // Not reached: follow the power law fitted to all points (one noisy segment would
    // give a wild answer), if the error falls at all.
    const std::optional<LogLogFit> fit = fit_log_log(seconds, error);
    if (!fit || !(fit->slope < 0)) return std::nullopt;
    return TimeToError{std::exp((std::log(target) - fit->intercept) / fit->slope), true,
                       false};
}

}  // namespace penumbra
