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

// The profile is evaluated once on a radial table 64 times finer than the
// cell and interpolated linearly: O(N^2) lookups rather than O(N^2)
// multipole sums.
Spectrum FftGrid::kernel(double total, const std::function<double(double)>& profile) const {
    const int n = n_;
    std::vector<float> k(size_t(n) * n, 0.0f);
    const double r_max = n * cell_ / 4.0;
    constexpr int kFine = 64;
    const double step = cell_ / kFine;
    std::vector<double> table(size_t(std::ceil(r_max / step)) + 2);
    for (size_t i = 0; i < table.size(); ++i) table[i] = profile(double(i) * step);
    double sum = 0.0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double dx = std::min(x, n - x) * cell_, dy = std::min(y, n - y) * cell_;
            const double r = std::sqrt(dx * dx + dy * dy);
            if (r > r_max) continue;
            const double f = r / step;
            const auto i = size_t(f);
            const double t = f - double(i);
            const double v = (table[i] * (1.0 - t) + table[i + 1] * t) * cell_ * cell_;
            k[size_t(y) * n + x] = float(v);
            sum += v;
        }
    if (sum > 0.0)
        for (float& v : k) v = float(v * (total / sum));
    return transform(k);
}

std::vector<double> FftGrid::radial_profile(const Spectrum& s) const {
    const int n = n_, bins = n / 2;
    const std::vector<float> space = back(s);
    std::vector<double> sum(size_t(bins), 0.0), count(size_t(bins), 0.0);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double dx = std::min(x, n - x), dy = std::min(y, n - y);
            const int b = int(std::sqrt(dx * dx + dy * dy) + 0.5);
            if (b >= bins) continue;
            sum[size_t(b)] += space[size_t(y) * n + x];
            count[size_t(b)] += 1.0;
        }
    std::vector<double> profile(static_cast<size_t>(bins));
    for (int b = 0; b < bins; ++b)
        profile[size_t(b)] = std::max(sum[size_t(b)] / (count[size_t(b)] * cell_ * cell_), 0.0);  // NaN passes
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
