// profile_convolution.cpp: see profile_convolution.h. Each convolution is
// integral over r of R(r) 2 pi r w(r), where w(r) is the lit fraction of the
// circle of radius r around the point; w is smooth between its kinks (where
// the circle first touches the edge and where it leaves it), so the range
// is split there and each piece integrated adaptively.
#include "reference/profile_convolution.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace st::reference {

namespace {

constexpr double kPi = std::numbers::pi;

// Gauss-Kronrod 7/15 nodes and weights on [-1, 1].
constexpr double kXgk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                            0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                            0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                            0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
constexpr double kWgk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                            0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                            0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                            0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr double kWg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                           0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

struct Piece {
    double value, error;
};

template <class F>
Piece kronrod(const F& f, double a, double b) {
    const double c = 0.5 * (a + b), h = 0.5 * (b - a);
    const double fc = f(c);
    double k = fc * kWgk[7], g = fc * kWg[3];
    for (int j = 0; j < 7; ++j) {
        const double x = h * kXgk[j];
        const double f1 = f(c - x), f2 = f(c + x);
        k += kWgk[j] * (f1 + f2);
        if (j % 2 == 1) g += kWg[j / 2] * (f1 + f2);
    }
    return {k * h, std::abs((k - g) * h)};
}

// Adaptive: bisect the piece with the largest error until the sum of the
// errors is under tolerance * |total| (or a piece budget runs out, which a
// smooth piecewise integrand never needs).
template <class F>
double integrate(const F& f, const std::vector<double>& breaks, double tolerance) {
    struct Interval {
        double a, b;
        Piece p;
    };
    std::vector<Interval> parts;
    for (size_t i = 0; i + 1 < breaks.size(); ++i)
        if (breaks[i + 1] > breaks[i]) parts.push_back({breaks[i], breaks[i + 1], kronrod(f, breaks[i], breaks[i + 1])});
    for (int round = 0; round < 20000; ++round) {
        double total = 0, error = 0;
        size_t worst = 0;
        for (size_t i = 0; i < parts.size(); ++i) {
            total += parts[i].p.value;
            error += parts[i].p.error;
            if (parts[i].p.error > parts[worst].p.error) worst = i;
        }
        if (parts.empty() || error <= tolerance * std::abs(total) || error < 1e-300) return total;
        const Interval w = parts[worst];
        const double m = 0.5 * (w.a + w.b);
        parts[worst] = {w.a, m, kronrod(f, w.a, m)};
        parts.push_back({m, w.b, kronrod(f, m, w.b)});
    }
    throw std::runtime_error("profile convolution: the integral did not converge");
}

void check(const RadialProfile& profile, const ConvolutionSettings& s) {
    if (!profile) throw std::invalid_argument("profile convolution: no profile");
    if (!(s.r_max > 0) || !std::isfinite(s.r_max)) throw std::invalid_argument("profile convolution: r_max must be > 0");
    if (!(s.tolerance > 0)) throw std::invalid_argument("profile convolution: tolerance must be > 0");
}

// Sorted, inside [0, r_max], with both ends: the kinks of the lit share,
// `inner`, and the profile's own.
std::vector<double> breakpoints(std::vector<double> inner, const ConvolutionSettings& s) {
    std::vector<double> b{0.0, s.r_max};
    for (double x : inner)
        if (x > 0 && x < s.r_max) b.push_back(x);
    for (double x : s.knots)
        if (x > 0 && x < s.r_max) b.push_back(x);
    std::sort(b.begin(), b.end());
    return b;
}

}  // namespace

double profile_total(const RadialProfile& profile, const ConvolutionSettings& s) {
    check(profile, s);
    auto f = [&](double r) { return profile(r) * 2 * kPi * r; };
    return integrate(f, breakpoints({}, s), s.tolerance);
}

double convolve_half_plane(const RadialProfile& profile, double d, const ConvolutionSettings& s) {
    check(profile, s);
    if (!std::isfinite(d)) throw std::invalid_argument("profile convolution: the distance to the edge is not finite");
    // The lit share of the circle of radius r: all of it inside the lit side
    // (r <= d), none beyond the dark side (r <= -d), else 1/2 + asin(d/r)/pi.
    auto f = [&](double r) {
        const double lit = r <= std::abs(d) ? (d > 0 ? 1.0 : d < 0 ? 0.0 : 0.5)
                                            : 0.5 + std::asin(std::clamp(d / r, -1.0, 1.0)) / kPi;
        return lit == 0 ? 0.0 : profile(r) * 2 * kPi * r * lit;
    };
    return integrate(f, breakpoints({std::abs(d)}, s), s.tolerance);
}

double convolve_disk(const RadialProfile& profile, double a, double rho, const ConvolutionSettings& s) {
    check(profile, s);
    if (!(a >= 0) || !std::isfinite(a) || !(rho >= 0) || !std::isfinite(rho))
        throw std::invalid_argument("profile convolution: the spot's radius and distance must be finite and >= 0");
    // The circle of radius r about a point rho from the centre of a disk of
    // radius a: inside it for r <= a - rho, outside for r >= a + rho or (for
    // a point outside the disk) r <= rho - a; between, the arc within the
    // disk spans 2 acos((r^2 + rho^2 - a^2) / (2 r rho)).
    auto f = [&](double r) {
        double lit;
        if (r <= a - rho) lit = 1.0;
        else if (r >= a + rho || r <= rho - a) lit = 0.0;
        else lit = std::acos(std::clamp((r * r + rho * rho - a * a) / (2 * r * rho), -1.0, 1.0)) / kPi;
        return lit == 0 ? 0.0 : profile(r) * 2 * kPi * r * lit;
    };
    return integrate(f, breakpoints({std::abs(a - rho), a + rho}, s), s.tolerance);
}

}  // namespace st::reference
