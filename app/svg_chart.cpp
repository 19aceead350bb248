// svg_chart.cpp: see svg_chart.h. Points that are not finite (or not
// positive on a log axis) break the line instead of distorting the chart.
#include "app/svg_chart.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace st {

namespace {

std::string esc(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '&') out += "&amp;";
        else out += c;
    }
    return out;
}

std::string tick_label(double v, bool log) {
    std::ostringstream s;
    if (log) s << "1e" << int(std::lround(std::log10(v)));
    else s << std::setprecision(3) << v;
    return s.str();
}

}  // namespace

std::string Chart::svg(int width, int height) const {
    const double left = 70, right = 170, top = 36, bottom = 50;
    const double pw = width - left - right, ph = height - top - bottom;
    auto usable_x = [&](double v) { return std::isfinite(v) && (!log_x || v > 0); };
    auto usable_y = [&](double v) { return std::isfinite(v) && (!log_y || v > 0); };
    double x0 = x_min, x1 = x_max, y0 = y_min, y1 = y_max;
    for (const auto& s : series)
        for (size_t i = 0; i < s.x.size(); ++i) {
            if (!usable_x(s.x[i]) || !usable_y(s.y[i])) continue;
            if (std::isnan(x_min)) x0 = std::isnan(x0) ? s.x[i] : std::min(x0, s.x[i]);
            if (std::isnan(x_max)) x1 = std::isnan(x1) ? s.x[i] : std::max(x1, s.x[i]);
            if (std::isnan(y_min)) y0 = std::isnan(y0) ? s.y[i] : std::min(y0, s.y[i]);
            if (std::isnan(y_max)) y1 = std::isnan(y1) ? s.y[i] : std::max(y1, s.y[i]);
        }
    if (std::isnan(x0) || std::isnan(y0)) return "<svg xmlns=\"http://www.w3.org/2000/svg\"/>\n";
    if (log_y) { y0 = std::pow(10.0, std::floor(std::log10(y0))); y1 = std::pow(10.0, std::ceil(std::log10(y1))); }
    if (log_x) { x0 = std::pow(10.0, std::floor(std::log10(x0))); x1 = std::pow(10.0, std::ceil(std::log10(x1))); }
    if (y1 <= y0) y1 = y0 + 1;
    if (x1 <= x0) x1 = x0 + 1;
    auto fx = [&](double v) {
        const double t = log_x ? (std::log10(v) - std::log10(x0)) / (std::log10(x1) - std::log10(x0)) : (v - x0) / (x1 - x0);
        return left + t * pw;
    };
    auto fy = [&](double v) {
        const double t = log_y ? (std::log10(v) - std::log10(y0)) / (std::log10(y1) - std::log10(y0)) : (v - y0) / (y1 - y0);
        return top + (1 - t) * ph;
    };
    std::ostringstream o;
    o << std::setprecision(6);
    o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    o << "<text x=\"" << left << "\" y=\"20\" font-size=\"13\">" << esc(title) << "</text>\n";
    // Grid and ticks.
    auto ticks = [](double a, double b, bool log) {
        std::vector<double> t;
        if (log) {
            const int step = std::max(1, int(std::ceil((std::log10(b) - std::log10(a)) / 8)));
            for (int e = int(std::floor(std::log10(a))); e <= int(std::ceil(std::log10(b))); e += step) t.push_back(std::pow(10.0, e));
        } else {
            for (int i = 0; i <= 5; ++i) t.push_back(a + (b - a) * i / 5);
        }
        return t;
    };
    for (double t : ticks(x0, x1, log_x)) {
        if (t < x0 || t > x1) continue;
        o << "<line x1=\"" << fx(t) << "\" x2=\"" << fx(t) << "\" y1=\"" << top << "\" y2=\"" << top + ph
          << "\" stroke=\"#ddd\"/><text x=\"" << fx(t) << "\" y=\"" << top + ph + 16 << "\" text-anchor=\"middle\">"
          << tick_label(t, log_x) << "</text>\n";
    }
    for (double t : ticks(y0, y1, log_y)) {
        if (t < y0 || t > y1) continue;
        o << "<line x1=\"" << left << "\" x2=\"" << left + pw << "\" y1=\"" << fy(t) << "\" y2=\"" << fy(t)
          << "\" stroke=\"#ddd\"/><text x=\"" << left - 6 << "\" y=\"" << fy(t) + 4 << "\" text-anchor=\"end\">"
          << tick_label(t, log_y) << "</text>\n";
    }
    o << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << pw << "\" height=\"" << ph
      << "\" fill=\"none\" stroke=\"black\"/>\n";
    o << "<text x=\"" << left + pw / 2 << "\" y=\"" << height - 12 << "\" text-anchor=\"middle\">" << esc(x_label) << "</text>\n";
    o << "<text transform=\"translate(16," << top + ph / 2 << ") rotate(-90)\" text-anchor=\"middle\">" << esc(y_label)
      << "</text>\n";
    int legend = 0;
    for (const auto& s : series) {
        if (s.dot_radius > 0) {
            for (size_t i = 0; i < s.x.size(); ++i) {
                if (!usable_x(s.x[i]) || !usable_y(s.y[i]) || s.x[i] < x0 || s.x[i] > x1) continue;
                o << "<circle cx=\"" << fx(s.x[i]) << "\" cy=\"" << std::clamp(fy(s.y[i]), top, top + ph) << "\" r=\""
                  << s.dot_radius << "\" fill=\"" << s.colour << "\"/>\n";
            }
            const double ly = top + 10 + 16 * legend++;
            o << "<circle cx=\"" << left + pw + 20 << "\" cy=\"" << ly << "\" r=\"" << s.dot_radius << "\" fill=\""
              << s.colour << "\"/><text x=\"" << left + pw + 34 << "\" y=\"" << ly + 4 << "\">" << esc(s.name)
              << "</text>\n";
            continue;
        }
        o << "<path fill=\"none\" stroke=\"" << s.colour << "\" stroke-width=\"1.5\""
          << (s.dashed ? " stroke-dasharray=\"5,3\"" : "") << " d=\"";
        bool pen = false;
        for (size_t i = 0; i < s.x.size(); ++i) {
            const bool ok = usable_x(s.x[i]) && usable_y(s.y[i]) && s.x[i] >= x0 && s.x[i] <= x1;
            if (!ok) { pen = false; continue; }
            const double py = std::clamp(fy(s.y[i]), top, top + ph);
            o << (pen ? "L" : "M") << fx(s.x[i]) << "," << py << " ";
            pen = true;
        }
        o << "\"/>\n";
        const double ly = top + 10 + 16 * legend++;
        o << "<line x1=\"" << left + pw + 10 << "\" x2=\"" << left + pw + 30 << "\" y1=\"" << ly << "\" y2=\"" << ly
          << "\" stroke=\"" << s.colour << "\" stroke-width=\"2\"" << (s.dashed ? " stroke-dasharray=\"5,3\"" : "")
          << "/><text x=\"" << left + pw + 34 << "\" y=\"" << ly + 4 << "\">" << esc(s.name) << "</text>\n";
    }
    o << "</svg>\n";
    return o.str();
}

}  // namespace st
