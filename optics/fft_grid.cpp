// fft_grid.cpp: see fft_grid.h.
//
// 2D real FFT as rows (kiss_fftr) then columns (kiss_fft). Debian's KissFFT
// 131.1.0 cannot plan kiss_fftndr grids (its size computation overflows), so
// the two passes are written out here. It is float-only: profile values
// carry about 1e-7 of the peak as noise.
#include "optics/fft_grid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace st::optics {

FftGrid::FftGrid(int n, double cell) : n_(n), cell_(cell) {
    // The kernel's radial table has 64 entries a cell: a cell that is not a
    // normal positive number (1e-320 mm is denormal, a quarter of it 0) makes
    // its index arithmetic overflow.
    if (!(n >= 2) || (n & (n - 1)) != 0) throw std::invalid_argument("FftGrid: the grid must be a power of two >= 2");
    if (!std::isnormal(cell) || !(cell > 0.0) || !std::isnormal(cell / 64.0))
        throw std::invalid_argument("FftGrid: the cell must be a positive normal number of mm");
    row_forward_ = kiss_fftr_alloc(n, 0, nullptr, nullptr);
    row_inverse_ = kiss_fftr_alloc(n, 1, nullptr, nullptr);
    col_forward_ = kiss_fft_alloc(n, 0, nullptr, nullptr);
    col_inverse_ = kiss_fft_alloc(n, 1, nullptr, nullptr);
    if (!row_forward_ || !row_inverse_ || !col_forward_ || !col_inverse_)
        throw std::runtime_error("KissFFT: cannot plan a grid of that size");
}

FftGrid::~FftGrid() {
    kiss_fftr_free(row_forward_);
    kiss_fftr_free(row_inverse_);
    kiss_fft_free(col_forward_);
    kiss_fft_free(col_inverse_);
}

namespace {
constexpr int kFine = 64;  // entries of the radial table per cell
}  // namespace

size_t FftGrid::kernel_samples() const {
    const double r_max = n_ * cell_ / 4.0, step = cell_ / kFine;
    return size_t(std::ceil((r_max + cell_) / step)) + 2;
}

// The profile is evaluated once on a radial table 64 times finer than the
// cell and interpolated linearly: O(N^2) lookups rather than O(N^2)
// multipole sums. Each cell holds the profile's mean over the cell, not its
// value at the centre: near the source a profile can be far narrower than a
// cell (a 1.5 mm cell over a 0.1 mm mean free path held 21 times the total
// at its centre, and normalising then scaled the whole profile by 1/21), so
// cells near the centre are averaged over many points, the rest over few.
Spectrum FftGrid::kernel(double total, const std::function<double(double)>& profile, double* cut) const {
    const int n = n_;
    std::vector<float> k(size_t(n) * n, 0.0f);
    const double r_max = n * cell_ / 4.0;
    const double step = cell_ / kFine;
    std::vector<double> table(kernel_samples());
    for (size_t i = 0; i < table.size(); ++i) table[i] = profile(double(i) * step);
    auto at = [&](double r) {
        const double f = r / step;
        const auto i = size_t(f);
        const double t = f - double(i);
        return table[i] * (1.0 - t) + table[i + 1] * t;
    };
    // The kernel is symmetric in x, y and their swap: one mean per (cx, cy)
    // with cx >= cy, in cells from the centre.
    const int half = n / 2;
    std::vector<double> cell_mean(size_t(half + 1) * size_t(half + 1), -1.0);
    auto mean_of = [&](int cx, int cy) {
        if (cx < cy) std::swap(cx, cy);
        double& m = cell_mean[size_t(cy) * size_t(half + 1) + size_t(cx)];
        if (m >= 0.0) return m;
        const double dx = cx * cell_, dy = cy * cell_;
        const int sub = cx <= 2 ? 64 : cx <= 8 ? 8 : 1;  // points per side
        double mean = 0.0;
        for (int j = 0; j < sub; ++j)
            for (int i = 0; i < sub; ++i) {
                const double px = dx + ((i + 0.5) / sub - 0.5) * cell_;
                const double py = dy + ((j + 0.5) / sub - 0.5) * cell_;
                mean += at(std::sqrt(px * px + py * py));
            }
        m = mean / (double(sub) * sub);
        return m;
    };
    double sum = 0.0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const int cx = std::min(x, n - x), cy = std::min(y, n - y);
            const double dx = cx * cell_, dy = cy * cell_;
            if (std::sqrt(dx * dx + dy * dy) > r_max) continue;
            const double v = mean_of(cx, cy) * cell_ * cell_;
            k[size_t(y) * n + x] = float(v);
            sum += v;
        }
    if (sum > 0.0)
        for (float& v : k) v = float(v * (total / sum));
    if (cut && total > 0.0) {
        // The tail beyond r_max, where the profile is smooth: trapezoids in
        // ln r (steps of 5 %), out to 1000 r_max or until the integrand,
        // profile r^2, has fallen below 1e-12 of the total. Measured per unit
        // of light in, not per unit of the total: a faint, wide transmission
        // kernel cut off matters as little as it weighs.
        constexpr double kRatio = 1.05;
        const double du = std::log(kRatio);
        double r = r_max, tail = 0.0, previous = profile(r) * r * r;
        while (r < 1000.0 * r_max) {
            r *= kRatio;
            const double v = profile(r) * r * r;
            tail += 0.5 * (previous + v) * du;
            previous = v;
            if (v < 1e-12 * total) break;
        }
        *cut = std::max(*cut, std::min(1.0, 2.0 * 3.14159265358979323846 * tail));
    }
    return transform(k);
}

// The cells are averaged over annuli one cell wide (the cells whose centre
// rounds to b cells from the source). Those cells' mean radius wanders
// around b, which left a +-3 % ripple on a smooth profile, so each annulus
// also keeps its mean radius, and the profile at b cells is interpolated
// between the annuli at their mean radii (in the logarithm where both are
// positive: profiles fall off exponentially). Bilinear interpolation in the
// plane instead smeared a sharp centre cell over its neighbours.
std::vector<double> FftGrid::radial_profile(const Spectrum& s) const {
    const int n = n_, bins = n / 2;
    const std::vector<float> space = back(s);
    std::vector<double> sum(size_t(bins) + 1, 0.0), count(size_t(bins) + 1, 0.0), radius(size_t(bins) + 1, 0.0);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double dx = std::min(x, n - x), dy = std::min(y, n - y), rc = std::sqrt(dx * dx + dy * dy);
            const int b = int(rc + 0.5);
            if (b > bins) continue;
            sum[size_t(b)] += space[size_t(y) * n + x];
            radius[size_t(b)] += rc;
            count[size_t(b)] += 1.0;
        }
    std::vector<double> mean(size_t(bins) + 1), at(size_t(bins) + 1);
    for (size_t b = 0; b <= size_t(bins); ++b) {
        mean[b] = sum[b] / (count[b] * cell_ * cell_);
        at[b] = radius[b] / count[b];
    }
    std::vector<double> profile(static_cast<size_t>(bins));
    profile[0] = std::max(mean[0], 0.0);
    for (int b = 1; b < bins; ++b) {
        // The annulus pair around radius b: j with at[j] <= b < at[j + 1],
        // but never the centre cell, which is no sample of a smooth profile
        // when the peak is narrower than a cell (at[1] = 1.2: a short
        // extrapolation from annuli 1 and 2 instead).
        size_t j = size_t(b);
        if (j > 1 && at[j] > b) --j;
        const double t = (b - at[j]) / (at[j + 1] - at[j]);
        const double lo = mean[j], hi = mean[j + 1];
        const double v = lo > 0.0 && hi > 0.0 ? std::exp(std::log(lo) + t * (std::log(hi) - std::log(lo)))
                                              : lo + t * (hi - lo);
        profile[size_t(b)] = std::max(v, 0.0);  // NaN passes
    }
    return profile;
}

Spectrum FftGrid::transform(const std::vector<float>& in) const {
    const int n = n_, columns = n / 2 + 1;
    Spectrum out(size_t(n) * size_t(columns));
    for (int y = 0; y < n; ++y)
        kiss_fftr(row_forward_, &in[size_t(y) * n], reinterpret_cast<kiss_fft_cpx*>(&out[size_t(y) * columns]));
    std::vector<std::complex<float>> a(static_cast<size_t>(n)), b(static_cast<size_t>(n));
    for (int k = 0; k < columns; ++k) {
        for (int y = 0; y < n; ++y) a[size_t(y)] = out[size_t(y) * columns + k];
        kiss_fft(col_forward_, reinterpret_cast<kiss_fft_cpx*>(a.data()), reinterpret_cast<kiss_fft_cpx*>(b.data()));
        for (int y = 0; y < n; ++y) out[size_t(y) * columns + k] = b[size_t(y)];
    }
    return out;
}

std::vector<float> FftGrid::back(Spectrum in) const {
    const int n = n_, columns = n / 2 + 1;
    std::vector<std::complex<float>> a(static_cast<size_t>(n)), b(static_cast<size_t>(n));
    for (int k = 0; k < columns; ++k) {
        for (int y = 0; y < n; ++y) a[size_t(y)] = in[size_t(y) * columns + k];
        kiss_fft(col_inverse_, reinterpret_cast<kiss_fft_cpx*>(a.data()), reinterpret_cast<kiss_fft_cpx*>(b.data()));
        for (int y = 0; y < n; ++y) in[size_t(y) * columns + k] = b[size_t(y)];
    }
    std::vector<float> out(size_t(n) * n);
    for (int y = 0; y < n; ++y)
        kiss_fftri(row_inverse_, reinterpret_cast<const kiss_fft_cpx*>(&in[size_t(y) * columns]), &out[size_t(y) * n]);
    for (float& v : out) v /= float(n) * float(n);
    return out;
}

}  // namespace st::optics
