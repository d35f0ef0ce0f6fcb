#include "plot.h"

#include <algorithm>
#include <cmath>

#include "strf.h"

namespace hexc::bench {
namespace {

constexpr double kWidth = 820, kHeight = 500;
constexpr double kLeft = 70, kRight = 580, kTop = 40, kBottom = 440;  // the plot area
const char* const kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd"};

std::string escape(const std::string& text) {
    std::string out;
    for (char c : text) out += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
    return out;
}

std::string text(double x, double y, const std::string& s, const std::string& attributes = "") {
    return strf("<text x=\"%.1f\" y=\"%.1f\" %s>%s</text>\n", x, y, attributes.c_str(), escape(s).c_str());
}

// 1, 2 or 5 times a power of ten, about span / 6.
double tickStep(double span) {
    const double raw = span / 6, decade = std::pow(10, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0})
        if (m * decade >= raw) return m * decade;
    return 10 * decade;
}

// A label's text box: baseline at y, kLabelHeight tall, about 6 px per character at font size 10.
struct Box {
    double x, y, width;
};
constexpr double kLabelHeight = 11;

// Methods of similar cost and error land on top of each other: try the label right of its point, then left of it,
// one line further down or up each time, until it overlaps no label placed before it.
Box placeLabel(double pointX, double pointY, const std::string& label, std::vector<Box>& placed) {
    auto overlaps = [&](const Box& a) {
        return std::any_of(placed.begin(), placed.end(),
                           [&](const Box& b) { return a.x < b.x + b.width && b.x < a.x + a.width && std::abs(a.y - b.y) < kLabelHeight; });
    };
    const double width = 6.0 * double(label.size());
    Box box{pointX + 6, pointY - 5, width};
    for (int step = 1; overlaps(box) && step < 40; ++step) {
        const int line = step / 2;
        box.x = step % 2 ? pointX - 6 - width : pointX + 6;
        box.y = pointY - 5 + kLabelHeight * (line % 2 ? (line + 1) / 2 : -line / 2);
    }
    placed.push_back(box);
    return box;
}

bool plottable(const PlotPoint& p) { return std::isfinite(p.x) && std::isfinite(p.y) && p.y > 0; }

}  // namespace

std::string scatterSvg(const std::string& title, const std::string& xLabel, const std::string& yLabel,
                       const std::vector<std::string>& seriesNames, const std::vector<PlotPoint>& points,
                       const std::vector<XMarker>& markers, const std::vector<std::string>& notes) {
    std::vector<PlotPoint> shown;
    std::copy_if(points.begin(), points.end(), std::back_inserter(shown), plottable);
    double xMax = 1, yMin = 1, yMax = 1e-3;
    for (const XMarker& m : markers) xMax = std::max(xMax, m.x);
    for (const PlotPoint& p : shown) {
        xMax = std::max(xMax, p.x);
        yMin = std::min(yMin, p.y);
        yMax = std::max(yMax, p.y);
    }
    const double xStep = tickStep(xMax);
    xMax = std::ceil(xMax * 1.05 / xStep) * xStep;
    const int decadeLo = int(std::floor(std::log10(yMin))), decadeHi = std::max(decadeLo + 1, int(std::ceil(std::log10(yMax))));
    auto px = [&](double x) { return kLeft + x / xMax * (kRight - kLeft); };
    auto py = [&](double y) { return kBottom - (std::log10(y) - decadeLo) / (decadeHi - decadeLo) * (kBottom - kTop); };

    std::string svg =
        strf("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%g\" height=\"%g\" font-family=\"sans-serif\" font-size=\"12\">\n", kWidth,
             kHeight);
    svg += strf("<rect width=\"%g\" height=\"%g\" fill=\"white\"/>\n", kWidth, kHeight);
    svg += text(kLeft, 22, title, "font-size=\"15\" font-weight=\"bold\"");
    // Axes, grid and ticks.
    for (double x = 0; x <= xMax + xStep / 2; x += xStep) {
        svg += strf("<line x1=\"%.1f\" y1=\"%g\" x2=\"%.1f\" y2=\"%g\" stroke=\"#ddd\"/>\n", px(x), kTop, px(x), kBottom);
        svg += text(px(x), kBottom + 16, strf("%g", x), "text-anchor=\"middle\"");
    }
    for (int d = decadeLo; d <= decadeHi; ++d) {
        svg += strf("<line x1=\"%g\" y1=\"%.1f\" x2=\"%g\" y2=\"%.1f\" stroke=\"#ddd\"/>\n", kLeft, py(std::pow(10, d)), kRight,
                    py(std::pow(10, d)));
        svg += text(kLeft - 6, py(std::pow(10, d)) + 4, strf("1e%d", d), "text-anchor=\"end\"");
    }
    for (const XMarker& m : markers) {
        svg += strf("<line x1=\"%.1f\" y1=\"%g\" x2=\"%.1f\" y2=\"%g\" stroke=\"#888\" stroke-dasharray=\"2 3\"/>\n", px(m.x), kTop,
                    px(m.x), kBottom);
        svg += text(px(m.x) + 4, kTop + 12, m.label, "font-size=\"10\" fill=\"#666\"");
    }
    svg += strf("<rect x=\"%g\" y=\"%g\" width=\"%g\" height=\"%g\" fill=\"none\" stroke=\"black\"/>\n", kLeft, kTop, kRight - kLeft,
                kBottom - kTop);
    svg += text((kLeft + kRight) / 2, kBottom + 40, xLabel, "text-anchor=\"middle\"");
    svg += text(18, (kTop + kBottom) / 2, yLabel, strf("text-anchor=\"middle\" transform=\"rotate(-90 18 %g)\"", (kTop + kBottom) / 2));

    std::vector<Box> labels;
    for (size_t s = 0; s < seriesNames.size(); ++s) {
        const char* colour = kColours[s % std::size(kColours)];
        // Pareto front: walking from the fastest point, keep each point more accurate than all faster ones
        // (by more than float noise: equal images compiled differently are not an improvement).
        std::vector<PlotPoint> series;
        for (const PlotPoint& p : shown)
            if (p.series == s && p.onFront) series.push_back(p);
        std::sort(series.begin(), series.end(), [](const auto& a, const auto& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
        std::string front;
        double best = INFINITY;
        for (const PlotPoint& p : series)
            if (p.y < best * (1 - 1e-6)) {
                best = p.y;
                front += strf("%.1f,%.1f ", px(p.x), py(p.y));
            }
        svg += strf("<polyline points=\"%s\" fill=\"none\" stroke=\"%s\" stroke-width=\"1.5\" stroke-dasharray=\"5 3\"/>\n", front.c_str(),
                    colour);
        for (const PlotPoint& p : shown) {
            if (p.series != s) continue;
            svg += strf("<circle cx=\"%.1f\" cy=\"%.1f\" r=\"4\" stroke=\"%s\" fill=\"%s\"/>\n", px(p.x), py(p.y), colour,
                        p.onFront ? colour : "white");
            const Box label = placeLabel(px(p.x), py(p.y), p.label, labels);
            svg += text(label.x, label.y, p.label, strf("font-size=\"10\" fill=\"%s\"", colour));
        }
        // Legend entry.
        const double ly = kTop + 10 + 20 * double(s);
        svg += strf("<circle cx=\"%g\" cy=\"%g\" r=\"4\" fill=\"%s\"/>\n", kRight + 20, ly - 4, colour);
        svg += text(kRight + 30, ly, seriesNames[s] + " (dashed: Pareto front)");
    }
    for (size_t i = 0; i < notes.size(); ++i)
        svg += text(kRight + 14, kTop + 30 + 20 * double(seriesNames.size() + i), notes[i], "font-size=\"11\"");
    return svg + "</svg>\n";
}

}  // namespace hexc::bench
