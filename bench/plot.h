#pragma once
// A scatter plot of run time against error as a self-contained SVG: linear x, logarithmic y, labelled points,
// and per series the Pareto front (no other point of the series is both faster and more accurate).
#include <string>
#include <vector>

namespace hexc::bench {

struct PlotPoint {
    std::string label;
    size_t series = 0;    // index into the series names; one colour each
    double x = 0, y = 0;  // points with a non-finite x or y, or y <= 0, are left out (a log axis cannot show them)
    bool onFront = true;  // may be part of the Pareto front; drawn hollow when false
};

// A vertical line across the plot, e.g. a target.
struct XMarker {
    double x = 0;
    std::string label;
};

// `notes` are extra legend lines, e.g. what hollow points mean.
std::string scatterSvg(const std::string& title, const std::string& xLabel, const std::string& yLabel,
                       const std::vector<std::string>& seriesNames, const std::vector<PlotPoint>& points,
                       const std::vector<XMarker>& markers, const std::vector<std::string>& notes);

}  // namespace hexc::bench
