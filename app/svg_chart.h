// svg_chart.h: small line charts as standalone SVG files, for the docs.
// Log or linear axes, several named series; no dependencies.
#pragma once

#include <cmath>
#include <string>
#include <vector>

namespace st {

struct ChartSeries {
    std::string name;
    std::string colour;  // CSS colour
    std::vector<double> x, y;
    bool dashed = false;
    // A scatter: a dot of this radius at each point, no line (0: a line).
    double dot_radius = 0;
};

struct Chart {
    std::string title, x_label, y_label;
    bool log_x = false, log_y = false;
    std::vector<ChartSeries> series;
    // Axis ranges; NaN = from the data.
    double x_min = NAN, x_max = NAN, y_min = NAN, y_max = NAN;

    std::string svg(int width = 640, int height = 400) const;
};

}  // namespace st
