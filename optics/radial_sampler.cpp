// radial_sampler.cpp: see radial_sampler.h. The reach is found by doubling
// r until the total gained over [r, 2r] is under tail_fraction of the whole
// (a profile falling at least exponentially loses less than that beyond 2r);
// the cumulative share is then tabulated on radii r_max u^2, u uniform, dense
// near 0 where the profile is steep, and inverted by interpolation.
#include "optics/radial_sampler.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "reference/profile_convolution.h"

namespace st::optics {

namespace {
constexpr int kTable = 4097;
constexpr double kPi = std::numbers::pi;
}  // namespace

RadialSampler::RadialSampler(std::function<double(double)> profile, double tail_fraction)
    : profile_(std::move(profile)) {
    if (!profile_) throw std::invalid_argument("radial sampler: no profile");
    if (!(tail_fraction > 0 && tail_fraction < 1)) throw std::invalid_argument("radial sampler: tail fraction outside (0, 1)");
    auto checked = [this](double r) {
        const double v = profile_(r);
        if (!std::isfinite(v) || v < 0)
            throw std::invalid_argument("radial sampler: the profile is negative or not finite at r = " + std::to_string(r));
        return v;
    };
    auto total_to = [&](double r) { return reference::profile_total(checked, reference::ConvolutionSettings{r, 1e-10, {}}); };
    double r = 1e-3, inner = total_to(r);
    for (;;) {
        if (r > 1e4) throw std::invalid_argument("radial sampler: the profile does not fall off within 1e4 mm");
        const double outer = total_to(2 * r);
        if (outer > 0 && outer - inner < tail_fraction * outer) {
            r_max_ = 2 * r;
            total_ = outer;
            break;
        }
        r *= 2;
        inner = outer;
    }
    if (!(total_ > 0)) throw std::invalid_argument("radial sampler: the profile is zero everywhere");
    // C on radii r_max u^2: Simpson's rule on each interval of the table,
    // midpoints included, and the whole scaled to total_.
    r_.resize(kTable);
    cumulative_.resize(kTable);
    auto f = [&](double x) { return checked(x) * 2 * kPi * x; };
    for (int i = 0; i < kTable; ++i) {
        const double u = double(i) / (kTable - 1);
        r_[size_t(i)] = r_max_ * u * u;
        if (i == 0) continue;
        const double a = r_[size_t(i - 1)], b = r_[size_t(i)];
        cumulative_[size_t(i)] = cumulative_[size_t(i - 1)] + (b - a) / 6 * (f(a) + 4 * f(0.5 * (a + b)) + f(b));
    }
    const double scale = 1.0 / cumulative_.back();
    for (double& c : cumulative_) c *= scale;
    cumulative_.back() = 1.0;
}

double RadialSampler::radius(double xi) const {
    if (!(xi >= 0 && xi <= 1)) throw std::invalid_argument("radial sampler: xi outside [0, 1]");
    const auto it = std::lower_bound(cumulative_.begin(), cumulative_.end(), xi);
    if (it == cumulative_.begin()) return 0.0;
    if (it == cumulative_.end()) return r_max_;
    const size_t i = size_t(it - cumulative_.begin());
    const double c0 = cumulative_[i - 1], c1 = cumulative_[i];
    const double t = c1 > c0 ? (xi - c0) / (c1 - c0) : 0.0;
    return r_[i - 1] + t * (r_[i] - r_[i - 1]);
}

std::vector<GatherSample> RadialSampler::importance_pattern(int n) const {
    if (n < 1) throw std::invalid_argument("radial sampler: a pattern needs at least one sample");
    const double golden = kPi * (3.0 - std::sqrt(5.0));
    std::vector<GatherSample> out(static_cast<size_t>(n));
    for (int k = 0; k < n; ++k) {
        const double r = radius((k + 0.5) / n), phi = k * golden;
        out[size_t(k)] = {r * std::cos(phi), r * std::sin(phi), total_ / n};
    }
    return out;
}

double radial_total(const std::function<double(double)>& profile, double tail_fraction) {
    if (reference::profile_total(profile, reference::ConvolutionSettings{1e4, 1e-10, {}}) == 0.0) return 0.0;
    return RadialSampler(profile, tail_fraction).total();
}

}  // namespace st::optics
