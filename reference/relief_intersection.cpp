// relief_intersection.cpp: see relief_intersection.h.
#include "reference/relief_intersection.h"

#include "reference/texel_breakpoints.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

namespace st::reference {

namespace {

constexpr double kMaxBreakpoints = 1e7;
constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr const char* kWho = "ReliefHeightField::first_crossing";

using breakpoints::reduce;
using breakpoints::wrap_index;

// c0 + c1 s + c2 s^2.
struct Quadratic {
    double c0 = 0, c1 = 0, c2 = 0;
    double at(double s) const { return c0 + s * (c1 + s * c2); }
};

// The smallest s in [0, len] with g(s) <= 0, given as a polynomial.
std::optional<double> first_nonpositive(const Quadratic& g, double len) {
    if (!(g.c0 > 0)) return 0.0;
    double best = std::numeric_limits<double>::infinity();
    const auto consider = [&](double s) {
        if (s >= 0 && s <= len && s < best) best = s;
    };
    if (g.c2 == 0) {
        if (g.c1 < 0) consider(-g.c0 / g.c1);
    } else {
        double disc = g.c1 * g.c1 - 4 * g.c2 * g.c0;
        // A ray grazing a smooth peak has a double root; rounding the
        // coefficients may push the discriminant just below zero and lose the
        // touch entirely, so a deficit within rounding counts as a touch (the
        // ray misses by less than ~1e-14 in height).
        const double slack =
            64 * kEps * (g.c1 * g.c1 + 4 * std::abs(g.c2) * (std::abs(g.c0) + 1));
        if (disc < 0 && disc >= -slack) disc = 0;
        if (disc >= 0) {
            // Both roots without cancellation (Numerical Recipes 5.6).
            const double q = -0.5 * (g.c1 + std::copysign(std::sqrt(disc), g.c1));
            consider(q / g.c2);
            if (q != 0) consider(g.c0 / q);
        }
    }
    if (best <= len) return best;
    // g > 0 at the start and <= 0 at the end means a root here, even if the
    // closed form put it a rounding error outside: bisect rather than skip to
    // the next interval, whose start would then be late.
    if (g.at(len) <= 0) {
        double lo = 0, hi = len;
        for (int k = 0; k < 200; ++k) {
            const double mid = 0.5 * (lo + hi);
            if (mid <= lo || mid >= hi) break;
            (g.at(mid) > 0 ? lo : hi) = mid;
        }
        return hi;
    }
    return std::nullopt;
}

}  // namespace

ReliefHeightField::ReliefHeightField(const Texture& t) {
    if (t.format != TextureFormat::RGBA8)
        throw std::invalid_argument("ReliefHeightField: the height texture must be RGBA8");
    if (t.wrap_s != TextureWrap::Repeat || t.wrap_t != TextureWrap::Repeat)
        throw std::invalid_argument("ReliefHeightField: the height texture must wrap with REPEAT");
    if (t.cube || !t.target.empty())
        throw std::invalid_argument("ReliefHeightField: needs a 2D texture with host texels");
    const auto add = [&](int w, int h, const std::vector<uint8_t>& texels) {
        if (w <= 0 || h <= 0 || texels.size() != size_t(w) * size_t(h) * 4)
            throw std::invalid_argument("ReliefHeightField: a level's size does not match its texels");
        Level level;
        level.width = w;
        level.height = h;
        level.h.resize(size_t(w) * size_t(h));
        for (size_t i = 0; i < level.h.size(); ++i) level.h[i] = texels[i * 4 + 3] / 255.0;
        levels_.push_back(std::move(level));
    };
    add(t.width, t.height, t.texels8);
    for (const TextureLevel& m : t.mips) add(m.width, m.height, m.texels8);
}

void ReliefHeightField::check_level(int level) const {
    if (level < 0 || level >= levels())
        throw std::invalid_argument("ReliefHeightField: no such level");
}

double ReliefHeightField::texel(int level, int x, int y) const {
    check_level(level);
    const Level& L = levels_[size_t(level)];
    return L.at(wrap_index(x, L.width), wrap_index(y, L.height));
}

double ReliefHeightField::height(int level, double u, double v) const {
    check_level(level);
    if (!std::isfinite(u) || !std::isfinite(v))
        throw std::invalid_argument("ReliefHeightField::height: non-finite coordinate");
    const Level& L = levels_[size_t(level)];
    const double x = reduce(u) * L.width - 0.5, y = reduce(v) * L.height - 0.5;
    const double i = std::floor(x), j = std::floor(y);
    const double fx = x - i, fy = y - j;
    const int x0 = wrap_index(i, L.width), x1 = wrap_index(i + 1, L.width);
    const int y0 = wrap_index(j, L.height), y1 = wrap_index(j + 1, L.height);
    return (1 - fx) * (1 - fy) * L.at(x0, y0) + fx * (1 - fy) * L.at(x1, y0) +
           (1 - fx) * fy * L.at(x0, y1) + fx * fy * L.at(x1, y1);
}

double ReliefHeightField::height(int level0, int level1, double f, double u, double v) const {
    check_level(level1);
    if (!(f >= 0 && f <= 1)) throw std::invalid_argument("ReliefHeightField::height: f outside [0, 1]");
    if (f == 0 || level0 == level1) return height(level0, u, v);
    return (1 - f) * height(level0, u, v) + f * height(level1, u, v);
}

ReliefHeightField::Crossing ReliefHeightField::first_crossing(int level0, int level1, double f,
                                                              double u0, double v0, double du,
                                                              double dv) const {
    for (double a : {f, u0, v0, du, dv})
        if (!std::isfinite(a))
            throw std::invalid_argument("ReliefHeightField::first_crossing: non-finite input");
    check_level(level0);
    check_level(level1);
    if (!(f >= 0 && f <= 1))
        throw std::invalid_argument("ReliefHeightField::first_crossing: f outside [0, 1]");

    // The levels that contribute, with their weights; a level weighted 0
    // would only add breakpoints.
    struct Term { const Level* level; double weight; };
    std::vector<Term> terms;
    if (f == 0 || level0 == level1) {
        terms.push_back({&levels_[size_t(level0)], 1.0});
    } else {
        if (f < 1) terms.push_back({&levels_[size_t(level0)], 1 - f});
        terms.push_back({&levels_[size_t(level1)], f});
    }

    const double ur = reduce(u0), vr = reduce(v0);
    std::vector<double> ts{0.0, 1.0};
    double budget = kMaxBreakpoints;
    for (const Term& term : terms) {
        breakpoints::add_integer_crossings(ts, budget, ur * term.level->width - 0.5, du * term.level->width, kWho);
        breakpoints::add_integer_crossings(ts, budget, vr * term.level->height - 0.5, dv * term.level->height, kWho);
    }
    std::sort(ts.begin(), ts.end());
    ts.erase(std::unique(ts.begin(), ts.end()), ts.end());

    const auto crossing_at = [&](double t) {
        const double u = u0 + t * du, v = v0 + t * dv;
        return Crossing{t, u, v, height(level0, level1, f, u, v)};
    };
    for (size_t k = 0; k + 1 < ts.size(); ++k) {
        const double ta = ts[k], tb = ts[k + 1], tm = 0.5 * (ta + tb);
        // H(ta + s) as a polynomial in the local s = t - ta: local, so a long
        // ray's large t * du does not cancel inside the coefficients.
        Quadratic H;
        for (const Term& term : terms) {
            const Level& L = *term.level;
            const double x0 = ur * L.width - 0.5, sx = du * L.width;
            const double y0 = vr * L.height - 0.5, sy = dv * L.height;
            // The cell is fixed inside the interval; its midpoint is safely
            // away from the boundaries where rounding could pick a neighbour.
            const double i = std::floor(x0 + tm * sx), j = std::floor(y0 + tm * sy);
            const double px = (x0 - i) + ta * sx, py = (y0 - j) + ta * sy;
            const int xa = wrap_index(i, L.width), xb = wrap_index(i + 1, L.width);
            const int ya = wrap_index(j, L.height), yb = wrap_index(j + 1, L.height);
            const double h00 = L.at(xa, ya), h10 = L.at(xb, ya);
            const double h01 = L.at(xa, yb), h11 = L.at(xb, yb);
            // Bilinear as h00 + A fx + B fy + C fx fy with fx = px + sx s,
            // fy = py + sy s; the fx fy product is the only s^2 term.
            const double A = h10 - h00, B = h01 - h00, C = h00 - h10 - h01 + h11;
            H.c0 += term.weight * (h00 + A * px + B * py + C * px * py);
            H.c1 += term.weight * (A * sx + B * sy + C * (px * sy + sx * py));
            H.c2 += term.weight * (C * sx * sy);
        }
        const Quadratic g{(1 - ta) - H.c0, -1 - H.c1, -H.c2};
        if (const std::optional<double> s = first_nonpositive(g, tb - ta))
            return crossing_at(std::min(ta + *s, tb));
    }
    // Only reachable by rounding: the floor stops every ray at t = 1.
    return crossing_at(1.0);
}

}  // namespace st::reference
