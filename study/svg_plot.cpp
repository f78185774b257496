#include "study/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace penumbra {

namespace {

constexpr double kWidth = 760, kHeight = 480;
constexpr double kLeft = 80, kRight = 200, kTop = 40, kBottom = 60;  // margins
constexpr double kPlotW = kWidth - kLeft - kRight, kPlotH = kHeight - kTop - kBottom;
const char* const kColors[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                               "#9467bd", "#8c564b", "#e377c2", "#17becf"};

std::string escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    }
    return out;
}

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", v);
    return buf;
}

// Whole decades covering [lo, hi] (log10 values), at least one.
struct Decades {
    int lo = 0, hi = 1;
    double map(double log_value, double length) const {
        return (log_value - lo) / (hi - lo) * length;
    }
};

Decades decades(double lo, double hi) {
    if (!(lo <= hi)) return {};
    Decades d{int(std::floor(std::log10(lo))), int(std::ceil(std::log10(hi)))};
    if (d.hi == d.lo) ++d.hi;
    return d;
}

// Grid and ticks: a labelled line per decade, short ticks at 2..9 times it; the frame
// and the axis labels.
std::string grid_and_axes(const Decades& dx, const Decades& dy, const PlotLabels& labels) {
    std::string svg;
    svg += "<g stroke=\"#ddd\">\n";
    for (int k = dx.lo; k <= dx.hi; ++k) {
        const double x = kLeft + dx.map(k, kPlotW);
        svg += "<line x1=\"" + num(x) + "\" y1=\"" + num(kTop) + "\" x2=\"" + num(x) +
               "\" y2=\"" + num(kTop + kPlotH) + "\"/>\n";
    }
    for (int k = dy.lo; k <= dy.hi; ++k) {
        const double y = kTop + kPlotH - dy.map(k, kPlotH);
        svg += "<line x1=\"" + num(kLeft) + "\" y1=\"" + num(y) + "\" x2=\"" +
               num(kLeft + kPlotW) + "\" y2=\"" + num(y) + "\"/>\n";
    }
    svg += "</g>\n<g stroke=\"black\">\n";
    for (int k = dx.lo; k < dx.hi; ++k)
        for (int m = 2; m <= 9; ++m) {
            const double x = kLeft + dx.map(k + std::log10(m), kPlotW);
            svg += "<line x1=\"" + num(x) + "\" y1=\"" + num(kTop + kPlotH) + "\" x2=\"" +
                   num(x) + "\" y2=\"" + num(kTop + kPlotH - 4) + "\"/>\n";
        }
    for (int k = dy.lo; k < dy.hi; ++k)
        for (int m = 2; m <= 9; ++m) {
            const double y = kTop + kPlotH - dy.map(k + std::log10(m), kPlotH);
            svg += "<line x1=\"" + num(kLeft) + "\" y1=\"" + num(y) + "\" x2=\"" +
                   num(kLeft + 4) + "\" y2=\"" + num(y) + "\"/>\n";
        }
    svg += "</g>\n<rect x=\"" + num(kLeft) + "\" y=\"" + num(kTop) + "\" width=\"" +
           num(kPlotW) + "\" height=\"" + num(kPlotH) + "\" fill=\"none\" stroke=\"black\"/>\n";
    for (int k = dx.lo; k <= dx.hi; ++k)
        svg += "<text x=\"" + num(kLeft + dx.map(k, kPlotW)) + "\" y=\"" +
               num(kTop + kPlotH + 18) + "\" text-anchor=\"middle\">10<tspan dy=\"-6\" "
               "font-size=\"9\">" + std::to_string(k) + "</tspan></text>\n";
    for (int k = dy.lo; k <= dy.hi; ++k)
        svg += "<text x=\"" + num(kLeft - 8) + "\" y=\"" +
               num(kTop + kPlotH - dy.map(k, kPlotH) + 4) + "\" text-anchor=\"end\">10<tspan "
               "dy=\"-6\" font-size=\"9\">" + std::to_string(k) + "</tspan></text>\n";
    svg += "<text x=\"" + num(kLeft + kPlotW / 2) + "\" y=\"" + num(kHeight - 16) +
           "\" text-anchor=\"middle\">" + escape(labels.x) + "</text>\n";
    svg += "<text transform=\"translate(22," + num(kTop + kPlotH / 2) +
           ") rotate(-90)\" text-anchor=\"middle\">" + escape(labels.y) + "</text>\n";

    return svg;
}

// Each series as a line with markers, its legend entry, and the guide's.
template <class Px, class Py>
std::string series_and_legend(const std::vector<PlotSeries>& series, Px px, Py py) {
    std::string svg;
    for (size_t i = 0; i < series.size(); ++i) {
        const PlotSeries& s = series[i];
        const char* color = kColors[i % (sizeof kColors / sizeof *kColors)];
        std::string points, markers;
        for (size_t j = 0; j < s.x.size() && j < s.y.size(); ++j) {
            if (!(s.x[j] > 0 && s.y[j] > 0 && std::isfinite(s.x[j]) && std::isfinite(s.y[j])))
                continue;
            points += (points.empty() ? "" : " ") + num(px(s.x[j])) + "," + num(py(s.y[j]));
            markers += "<circle cx=\"" + num(px(s.x[j])) + "\" cy=\"" + num(py(s.y[j])) +
                       "\" r=\"3\"/>";
        }
        svg += "<g fill=\"" + std::string(color) + "\"><polyline class=\"series\" points=\"" +
               points + "\" fill=\"none\" stroke=\"" + color + "\" stroke-width=\"2\"/>" +
               markers + "</g>\n";
        const double ly = kTop + 16 + 20 * i;
        svg += "<line x1=\"" + num(kLeft + kPlotW + 16) + "\" y1=\"" + num(ly - 4) +
               "\" x2=\"" + num(kLeft + kPlotW + 40) + "\" y2=\"" + num(ly - 4) +
               "\" stroke=\"" + color + "\" stroke-width=\"2\"/><text x=\"" +
               num(kLeft + kPlotW + 46) + "\" y=\"" + num(ly) + "\">" + escape(s.name) +
               "</text>\n";
    }
    const double ly = kTop + 16 + 20 * series.size();
    svg += "<line x1=\"" + num(kLeft + kPlotW + 16) + "\" y1=\"" + num(ly - 4) + "\" x2=\"" +
           num(kLeft + kPlotW + 40) + "\" y2=\"" + num(ly - 4) +
           "\" stroke=\"#888\" stroke-dasharray=\"6,4\"/><text x=\"" +
           num(kLeft + kPlotW + 46) + "\" y=\"" + num(ly) + "\">slope -1</text>\n";
    return svg;
}

}  // namespace

std::string log_log_plot_svg(const std::vector<PlotSeries>& series, const PlotLabels& labels) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    double x0 = inf, x1 = -inf, y0 = inf, y1 = -inf;
    for (const PlotSeries& s : series)
        for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
            if (s.x[i] > 0 && s.y[i] > 0 && std::isfinite(s.x[i]) && std::isfinite(s.y[i])) {
                x0 = std::min(x0, s.x[i]), x1 = std::max(x1, s.x[i]);
                y0 = std::min(y0, s.y[i]), y1 = std::max(y1, s.y[i]);
            }
    const Decades dx = decades(x0, x1), dy = decades(y0, y1);
    auto px = [&](double x) { return kLeft + dx.map(std::log10(x), kPlotW); };
    auto py = [&](double y) { return kTop + kPlotH - dy.map(std::log10(y), kPlotH); };

    std::string svg = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    svg += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(kWidth) + "\" height=\"" +
           num(kHeight) + "\" viewBox=\"0 0 " + num(kWidth) + " " + num(kHeight) +
           "\" font-family=\"sans-serif\" font-size=\"12\">\n";
    svg += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    svg += "<text x=\"" + num(kLeft + kPlotW / 2) + "\" y=\"24\" text-anchor=\"middle\" "
           "font-size=\"15\">" + escape(labels.title) + "</text>\n";

    svg += grid_and_axes(dx, dy, labels);

    // Clip the guide (it may leave the data range); series points are inside by design.
    svg += "<clipPath id=\"plot\"><rect x=\"" + num(kLeft) + "\" y=\"" + num(kTop) +
           "\" width=\"" + num(kPlotW) + "\" height=\"" + num(kPlotH) + "\"/></clipPath>\n";
    if (std::isfinite(x0) && x1 > x0) {
        // Through the first series' first point, falling one decade per decade of x.
        const PlotSeries& s = series.front();
        const double gx = s.x.empty() ? x0 : s.x[0], gy = s.y.empty() ? y1 : s.y[0];
        svg += "<line class=\"guide\" clip-path=\"url(#plot)\" x1=\"" + num(px(gx)) +
               "\" y1=\"" + num(py(gy)) + "\" x2=\"" + num(px(x1 * 10)) + "\" y2=\"" +
               num(py(gy * gx / (x1 * 10))) +
               "\" stroke=\"#888\" stroke-dasharray=\"6,4\"/>\n";
    }
    svg += series_and_legend(series, px, py);
    svg += "</svg>\n";
    return svg;
}

}  // namespace penumbra
