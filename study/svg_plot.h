// A hand-written log-log line plot in SVG (no plotting library): decade ticks and grid
// on both axes, one polyline with point markers per series, a legend, and a dashed
// slope -1 guide (error proportional to 1 / time, plain Monte Carlo).
#pragma once

#include <string>
#include <vector>

namespace penumbra {

struct PlotSeries {
    std::string name;
    std::vector<double> x, y;  // points with x <= 0 or y <= 0 are left out
};

struct PlotLabels {
    std::string title, x, y;
};

std::string log_log_plot_svg(const std::vector<PlotSeries>& series, const PlotLabels& labels);

}  // namespace penumbra
