// thin_slab_sweep.cpp: see thin_slab_sweep.h. The rows cover where the
// thin-slab formulas break down: tiny tau1 (1 - exp(-x) cancels), mu close to
// mu0 (Eq. 5's removable singularity) and grazing mu or mu0 (tau1/mu
// overflows).
#include "scene/thin_slab_sweep.h"

#include <cmath>

namespace st {

namespace {

double log_space(double lo, double hi, int i, int n) {
    return lo * std::pow(hi / lo, double(i) / double(n - 1));
}

SweepRow tau1_row(int n, float mu, float mu0, const std::string& name) {
    SweepRow row{name, "tau1", {}};
    for (int i = 0; i < n; ++i) {
        const double tau1 = log_space(1e-5, 10.0, i, n);
        row.samples.push_back({tau1, float(tau1), mu, mu0});
    }
    return row;
}

// mu = mu0 (1 + e): e from -1e-1 to -1e-8 on the left half, +1e-8 to +1e-1 on
// the right, so the singular point sits in the middle of the row.
SweepRow near_mu0_row(int n, float tau1, float mu0, const std::string& name) {
    SweepRow row{name, "(mu - mu0) / mu0", {}};
    const int half = n / 2;
    for (int i = 0; i < n; ++i) {
        const bool left = i < half;
        const double e = left ? -log_space(1e-1, 1e-8, i, half) : log_space(1e-8, 1e-1, i - half, n - half);
        const float mu = float(double(mu0) * (1.0 + e));
        row.samples.push_back({(double(mu) - mu0) / mu0, tau1, mu, mu0});
    }
    return row;
}

SweepRow grazing_row(int n, float tau1, float fixed, bool sweep_mu0, const std::string& name) {
    SweepRow row{name, sweep_mu0 ? "mu0" : "mu", {}};
    for (int i = 0; i < n; ++i) {
        const double c = log_space(1e-9, 1.0, i, n);
        row.samples.push_back(sweep_mu0 ? SweepSample{c, tau1, fixed, float(c)}
                                        : SweepSample{c, tau1, float(c), fixed});
    }
    return row;
}

}  // namespace

std::vector<SweepRow> thin_slab_sweep_rows(int n) {
    return {
        tau1_row(n, 1.0f, 1.0f, "tau1 sweep, mu = mu0 = 1"),
        tau1_row(n, 0.5f, 0.8f, "tau1 sweep, mu = 0.5, mu0 = 0.8"),
        tau1_row(n, 0.8f, 0.5f, "tau1 sweep, mu = 0.8, mu0 = 0.5"),
        near_mu0_row(n, 2.0f, 0.5f, "mu near mu0 = 0.5, tau1 = 2"),
        near_mu0_row(n, 0.2f, 0.5f, "mu near mu0 = 0.5, tau1 = 0.2"),
        near_mu0_row(n, 1e-4f, 0.9f, "mu near mu0 = 0.9, tau1 = 1e-4"),
        grazing_row(n, 2.0f, 0.7f, false, "grazing mu, tau1 = 2, mu0 = 0.7"),
        grazing_row(n, 1e-5f, 0.7f, false, "grazing mu, tau1 = 1e-5, mu0 = 0.7"),
        grazing_row(n, 2.0f, 0.7f, true, "grazing mu0, tau1 = 2, mu = 0.7"),
    };
}

}  // namespace st
