// fft_grid.h: the zero-padded Cartesian grid that frequency-space layering
// (optics/layered.h) works on: radial profiles laid out as wrapped kernels,
// their 2D real FFT (KissFFT), and radial averages back in space.
#pragma once

#include <complex>
#include <functional>
#include <vector>

#include <kissfft/kiss_fft.h>
#include <kissfft/kiss_fftr.h>

namespace st::optics {

// Spectrum layout: [row][column] with n / 2 + 1 columns; element 0 is the
// zero frequency, the kernel's total.
using Spectrum = std::vector<std::complex<float>>;

class FftGrid {
public:
    // n x n cells (a power of two) of `cell` mm.
    FftGrid(int n, double cell);
    ~FftGrid();
    FftGrid(const FftGrid&) = delete;
    FftGrid& operator=(const FftGrid&) = delete;

    int size() const { return n_; }
    double cell() const { return cell_; }
    Spectrum zero() const { return Spectrum(size_t(n_) * size_t(n_ / 2 + 1), 0.0f); }

    // The spectrum of a radial profile (per mm^2) sampled at cell centres,
    // centred on cell (0, 0) and wrapped, zero beyond a quarter of the grid
    // (so one convolution of two kernels cannot wrap around), scaled to sum
    // to `total` (so sampling a sharp peak cannot change the energy). If
    // `cut` is given, it is raised to the profile's integral beyond the
    // quarter grid (light per unit of light in).
    Spectrum kernel(double total, const std::function<double(double)>& profile, double* cut = nullptr) const;
    // How many radii kernel() evaluates the profile at (its radial table,
    // 64 a cell out to a quarter of the grid), besides a few for `cut`.
    size_t kernel_samples() const;

    // Back to space, per mm^2 at radii b * cell, b < n / 2: the cells
    // averaged over one-cell-wide annuli, interpolated to radius b between
    // the annuli's mean radii; negative values (float noise far out)
    // clamped to 0.
    std::vector<double> radial_profile(const Spectrum& s) const;

private:
    Spectrum transform(const std::vector<float>& in) const;
    std::vector<float> back(Spectrum in) const;

    int n_;
    double cell_;
    kiss_fftr_cfg row_forward_, row_inverse_;
    kiss_fft_cfg col_forward_, col_inverse_;
};

}  // namespace st::optics
