#include "core/convergence.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace penumbra {

namespace {

template <typename F>
double mean_over_rgb(const Image& image, const Image& reference, F per_channel) {
    CHECK(image.width == reference.width && image.height == reference.height,
          "image " << image.width << "x" << image.height << " vs reference "
                   << reference.width << "x" << reference.height);
    double sum = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const Vec4 a = image.rgba(x, y), r = reference.rgba(x, y);
            sum += per_channel(a.x, r.x) + per_channel(a.y, r.y) + per_channel(a.z, r.z);
        }
    const double n = 3.0 * image.width * image.height;
    return n > 0 ? sum / n : 0;
}

}  // namespace

double mean_squared_error(const Image& image, const Image& reference) {
    return mean_over_rgb(image, reference, [](double a, double r) { return (a - r) * (a - r); });
}

double relative_mse(const Image& image, const Image& reference, double epsilon) {
    return mean_over_rgb(image, reference, [epsilon](double a, double r) {
        return (a - r) * (a - r) / (r * r + epsilon);
    });
}

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
