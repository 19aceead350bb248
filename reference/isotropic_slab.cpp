// isotropic_slab.cpp: see isotropic_slab.h.
#include "reference/isotropic_slab.h"

#include <cmath>
#include <limits>
#include <vector>

namespace st {

double expint_e1(double x) {
    if (x <= 0.0) return std::numeric_limits<double>::infinity();
    if (x <= 1.0) {  // power series
        constexpr double euler = 0.57721566490153286061;
        double sum = 0.0, term = 1.0;
        for (int k = 1; k < 60; ++k) {
            term *= -x / k;
            sum += term / k;
            if (std::abs(term / k) < 1e-18) break;
        }
        return -euler - std::log(x) - sum;
    }
    // Continued fraction (modified Lentz) for x > 1.
    double b = x + 1.0, c = 1.0 / std::numeric_limits<double>::min(), d = 1.0 / b, h = d;
    for (int i = 1; i < 500; ++i) {
        const double a = -double(i) * i;
        b += 2.0;
        d = 1.0 / (a * d + b);
        c = b + a / c;
        const double del = c * d;
        h *= del;
        if (std::abs(del - 1.0) < 1e-16) break;
    }
    return h * std::exp(-x);
}

double expint_e2(double x) { return x <= 0.0 ? 1.0 : std::exp(-x) - x * expint_e1(x); }
double expint_e3(double x) { return x <= 0.0 ? 0.5 : 0.5 * (std::exp(-x) - x * expint_e2(x)); }

namespace {

// Integral of E1(|x - t|) over t in [a, b].
double e1_cell(double x, double a, double b) {
    if (x <= a) return expint_e2(a - x) - expint_e2(b - x);
    if (x >= b) return expint_e2(x - b) - expint_e2(x - a);
    return 2.0 - expint_e2(x - a) - expint_e2(b - x);
}

SlabFluxes solve(double tau1, double albedo, double mu0, int cells, bool single) {
    const double h = tau1 / cells;
    // Incident flux density 1/mu0 across the beam: irradiance 1 on the slab.
    const double beam = 1.0 / mu0;
    std::vector<double> s0(static_cast<size_t>(cells)), s;
    for (int j = 0; j < cells; ++j) {
        const double a = j * h, b = a + h;
        // Cell average of Lambda F/(4 pi) e^(-t/mu0).
        s0[size_t(j)] = albedo * beam / (4.0 * M_PI) * mu0 * (std::exp(-a / mu0) - std::exp(-b / mu0)) / h;
    }
    s = s0;
    if (!single) {
        std::vector<double> kernel(size_t(cells) * cells);
        for (int i = 0; i < cells; ++i)
            for (int j = 0; j < cells; ++j)
                kernel[size_t(i) * cells + j] = 0.5 * albedo * e1_cell((i + 0.5) * h, j * h, (j + 1) * h);
        // Gauss-Seidel; the operator's norm is below 1 (light leaks out).
        for (int iter = 0; iter < 100000; ++iter) {
            double change = 0.0;
            for (int i = 0; i < cells; ++i) {
                double v = s0[size_t(i)];
                const double* k = &kernel[size_t(i) * cells];
                for (int j = 0; j < cells; ++j) v += k[j] * s[size_t(j)];
                change = std::max(change, std::abs(v - s[size_t(i)]));
                s[size_t(i)] = v;
            }
            if (change < 1e-15) break;
        }
    }
    SlabFluxes f;
    for (int j = 0; j < cells; ++j) {
        const double a = j * h, b = a + h;
        f.reflectance += 2.0 * M_PI * s[size_t(j)] * (expint_e3(a) - expint_e3(b));
        f.transmittance += 2.0 * M_PI * s[size_t(j)] * (expint_e3(tau1 - b) - expint_e3(tau1 - a));
    }
    f.direct = std::exp(-tau1 / mu0);
    return f;
}

// Piecewise-constant collocation converges as h^2; Richardson on n and 2n.
SlabFluxes extrapolated(double tau1, double albedo, double mu0, bool single) {
    const int n = std::max(200, int(std::ceil(tau1 * 300.0)));
    const SlabFluxes coarse = solve(tau1, albedo, mu0, n, single);
    const SlabFluxes fine = solve(tau1, albedo, mu0, 2 * n, single);
    SlabFluxes r;
    r.reflectance = (4.0 * fine.reflectance - coarse.reflectance) / 3.0;
    r.transmittance = (4.0 * fine.transmittance - coarse.transmittance) / 3.0;
    r.direct = fine.direct;
    return r;
}

}  // namespace

SlabFluxes isotropic_slab_exact(double tau1, double albedo, double mu0) {
    return extrapolated(tau1, albedo, mu0, false);
}

SlabFluxes isotropic_slab_single(double tau1, double albedo, double mu0) {
    return extrapolated(tau1, albedo, mu0, true);
}

}  // namespace st
