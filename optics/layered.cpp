// layered.cpp: see layered.h.
//
// Kernels: a layer's profile sampled at cell centres times the cell area,
// laid out with its centre at cell (0, 0) and wrapped (minimum-image
// distances), zero beyond a quarter of the grid so that one convolution of
// two kernels cannot wrap around. Each kernel is scaled so that it sums to
// the layer's closed-form total: the sampling of the sharp peak near r = 0
// then cannot change the energy. For asymmetric layers the light that comes
// back up through layer 1 sees its reflectance from below:
//   R12 = R1 + T1 R2 T1' / (1 - R2 R1'),  T12 = T1 T2 / (1 - R2 R1'),
//   R12' = R2' + T2' R1' T2 / (1 - R1' R2), T12' = T2' T1' / (1 - R1' R2),
// which for two layers is Eq. 21-22 and recurses for more.
#include "optics/layered.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

#include <kissfft/kiss_fft.h>
#include <kissfft/kiss_fftr.h>

#include "optics/diffuse_fresnel.h"
#include "optics/multipole.h"
#include "optics/rough_surface.h"

namespace st::optics {

namespace {

using Spectrum = std::vector<std::complex<float>>;

// 2D real FFT as rows (kiss_fftr) then columns (kiss_fft). Debian's KissFFT
// 131.1.0 cannot plan kiss_fftndr grids (its size computation overflows), so
// the two passes are written out here. Spectrum layout: [row][column], with
// n / 2 + 1 columns; element 0 is the zero frequency (the total).
struct Fft {
    int n;
    kiss_fftr_cfg row_forward, row_inverse;
    kiss_fft_cfg col_forward, col_inverse;
    explicit Fft(int grid) : n(grid) {
        row_forward = kiss_fftr_alloc(grid, 0, nullptr, nullptr);
        row_inverse = kiss_fftr_alloc(grid, 1, nullptr, nullptr);
        col_forward = kiss_fft_alloc(grid, 0, nullptr, nullptr);
        col_inverse = kiss_fft_alloc(grid, 1, nullptr, nullptr);
        if (!row_forward || !row_inverse || !col_forward || !col_inverse)
            throw std::runtime_error("KissFFT: cannot plan a grid of that size");
    }
    ~Fft() {
        kiss_fftr_free(row_forward);
        kiss_fftr_free(row_inverse);
        kiss_fft_free(col_forward);
        kiss_fft_free(col_inverse);
    }
    Fft(const Fft&) = delete;
    Fft& operator=(const Fft&) = delete;

    int columns() const { return n / 2 + 1; }
    size_t spectrum_size() const { return size_t(n) * size_t(columns()); }

    Spectrum transform(const std::vector<float>& in) const {
        Spectrum out(spectrum_size());
        for (int y = 0; y < n; ++y)
            kiss_fftr(row_forward, &in[size_t(y) * n], reinterpret_cast<kiss_fft_cpx*>(&out[size_t(y) * columns()]));
        std::vector<std::complex<float>> a(static_cast<size_t>(n)), b(static_cast<size_t>(n));
        for (int k = 0; k < columns(); ++k) {
            for (int y = 0; y < n; ++y) a[size_t(y)] = out[size_t(y) * columns() + k];
            kiss_fft(col_forward, reinterpret_cast<kiss_fft_cpx*>(a.data()), reinterpret_cast<kiss_fft_cpx*>(b.data()));
            for (int y = 0; y < n; ++y) out[size_t(y) * columns() + k] = b[size_t(y)];
        }
        return out;
    }

    std::vector<float> back(Spectrum in) const {
        std::vector<std::complex<float>> a(static_cast<size_t>(n)), b(static_cast<size_t>(n));
        for (int k = 0; k < columns(); ++k) {
            for (int y = 0; y < n; ++y) a[size_t(y)] = in[size_t(y) * columns() + k];
            kiss_fft(col_inverse, reinterpret_cast<kiss_fft_cpx*>(a.data()), reinterpret_cast<kiss_fft_cpx*>(b.data()));
            for (int y = 0; y < n; ++y) in[size_t(y) * columns() + k] = b[size_t(y)];
        }
        std::vector<float> out(size_t(n) * n);
        for (int y = 0; y < n; ++y)
            kiss_fftri(row_inverse, reinterpret_cast<const kiss_fft_cpx*>(&in[size_t(y) * columns()]), &out[size_t(y) * n]);
        for (float& v : out) v /= float(n) * float(n);
        return out;
    }
};

// A radial profile as a wrapped, zero-padded kernel summing to `total`. The
// profile is evaluated once on a radial table 64 times finer than the cell
// and interpolated linearly, so a kernel costs O(N^2) lookups rather than
// O(N^2) multipole sums.
std::vector<float> kernel(int n, double cell, double total, const auto& profile) {
    std::vector<float> k(size_t(n) * n, 0.0f);
    const double r_max = n * cell / 4.0;
    constexpr int kFine = 64;
    const double step = cell / kFine;
    std::vector<double> table(size_t(std::ceil(r_max / step)) + 2);
    for (size_t i = 0; i < table.size(); ++i) table[i] = profile(double(i) * step);
    double sum = 0.0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double dx = std::min(x, n - x) * cell, dy = std::min(y, n - y) * cell;
            const double r = std::sqrt(dx * dx + dy * dy);
            if (r > r_max) continue;
            const double f = r / step;
            const auto i = size_t(f);
            const double t = f - double(i);
            const double v = (table[i] * (1.0 - t) + table[i + 1] * t) * cell * cell;
            k[size_t(y) * n + x] = float(v);
            sum += v;
        }
    if (sum > 0.0)
        for (float& v : k) v = float(v * (total / sum));
    return k;
}

double fresnel_normal(double eta) {
    const double r = (eta - 1.0) / (eta + 1.0);
    return r * r;
}

// What a layer's boundaries reflect of the light it passes on unscattered.
struct Boundaries {
    double top_normal;     // F at normal incidence, top (Fresnel)
    double bottom_normal;  // F at normal incidence, bottom
    double top_diffuse;    // F_dr of the top seen from inside: (A - 1) / (A + 1), Eq. 7 (Eq. 24 if rough)
};

// Where diffuse light that crosses a layer unscattered comes out, relative to
// where it went in: a Lambertian point source seen through a slab of
// thickness d, d^2 e^(-sigma_t' R) / (pi R^4) with R^2 = r^2 + d^2 (cosine
// out of the source, cosine onto the far plane, 1/R^2, attenuation along the
// slant path). Normalised to 1: the share that crosses is kept as the
// e^(-sigma_t' d) the totals were validated with; only its lateral spread is
// added (two 1 mm halves: R(4 mm) 0.00043 -> 0.00048 against Monte Carlo's
// 0.00068 /mm^2).
Spectrum diffuse_crossing(const Fft& fft, int n, double cell, const Slab& s) {
    const double d = s.thickness, sigma = s.sigma_t_reduced();
    return fft.transform(kernel(n, cell, 1.0, [&](double r) {
        const double R = std::sqrt(r * r + d * d);
        return d * d * std::exp(-sigma * (R - d)) / (R * R * R * R);  // e^(-sigma d) and 1/pi go with the scale
    }));
}

// The multipole with the first-scattering source leaves out the light that
// crosses a layer unscattered, e^(-sigma_t' d); the next layer must still
// receive it, as a delta at r = 0 (a constant in frequency space). The
// multipole's boundary conditions reflect the scattered light at the layer's
// interfaces but not this delta, so its Fresnel reflections are added here,
// to first order (the reflected part crosses the layer once more, unscattered
// or scattered):
// - going down it is the incident beam, collimated: the bottom reflects
//   F(0) of it, which comes back up through the layer;
// - going up it is light that lower layers scattered, diffuse: the top
//   reflects F_dr of it back down, as it does the diffusing light. Without
//   this a thin top layer under a reflective boundary (eta 1.4) let the light
//   from below escape at normal-incidence rates and the stack over-reflected
//   by up to 30 % against Monte Carlo (docs/optics.md). Being diffuse, it
//   also moves sideways as it crosses: each crossing convolves it with
//   `spread` (diffuse_crossing), which keeps its total.
void add_unscattered(double passes, const Boundaries& b, const Spectrum& spread, Spectrum& r, Spectrum& t,
                     Spectrum& rb, Spectrum& tb) {
    if (passes == 0.0) return;
    for (size_t k = 0; k < r.size(); ++k) {
        const std::complex<float> r0 = r[k], t0 = t[k], rb0 = rb[k], tb0 = tb[k], sp = spread[k];
        t[k] = t0 + float(passes * (1.0 - b.bottom_normal)) + float(passes * b.bottom_normal) * rb0;
        r[k] = r0 + float(passes * b.bottom_normal) * (float(passes * (1.0 - b.top_normal)) + tb0);
        tb[k] = tb0 + (float(passes * (1.0 - b.top_diffuse)) + float(passes * b.top_diffuse) * r0) * sp;
        rb[k] = rb0 + float(passes * b.top_diffuse) * (float(passes) * sp + t0) * sp;
    }
}

}  // namespace

LayeredResult combine_layers(const std::vector<LayerSpec>& layers, const LayeredOptions& o) {
    if (layers.empty()) throw std::invalid_argument("no layers");
    const int n = o.grid;
    // Absolute indices: air (1) above the first layer and below the last.
    std::vector<double> index{1.0};
    for (const LayerSpec& l : layers) index.push_back(index.back() * l.eta);
    index.push_back(1.0);

    double extent = o.extent;
    if (extent <= 0.0) {
        double mfp = 0.0;
        for (const LayerSpec& l : layers)
            for (int c = 0; c < 3; ++c) {
                const double st = l.sigma_a[size_t(c)] + l.sigma_s[size_t(c)] * (1.0 - l.g);
                if (st > 0.0) mfp = std::max(mfp, 1.0 / st);
            }
        extent = 16.0 * std::max(mfp, 1e-3) * 4.0;  // the kernels reach a quarter of it: 16 mfp
    }
    LayeredResult result;
    result.cell = extent / n;
    result.dipoles.assign(layers.size(), 0);
    const Fft fft(n);
    const Spectrum zero(fft.spectrum_size(), 0.0f);

    for (int c = 0; c < 3; ++c) {
        Spectrum R, T, Rb, Tb;  // the stack so far: from above, and from below
        double direct = 1.0 - fresnel_normal(index[1]);
        double unscattered_reduced = 1.0;  // product of e^(-sigma_t' d): the beam the kernels pass on as a delta
        double unscattered = 1.0;          // product of e^(-sigma_t d)
        for (size_t i = 0; i < layers.size(); ++i) {
            const LayerSpec& L = layers[i];
            Slab s;
            s.sigma_a = L.sigma_a[size_t(c)];
            s.sigma_s = L.sigma_s[size_t(c)];
            s.g = L.g;
            s.eta = index[i + 1] / index[i];
            s.eta_below = index[i + 1] / index[i + 2];
            s.thickness = L.thickness;
            if (L.roughness > 0.0) s.boundary_factor_top = rough_boundary_factor(L.roughness, s.eta);
            Slab flipped = s;
            std::swap(flipped.eta, flipped.eta_below);
            std::swap(flipped.boundary_factor_top, flipped.boundary_factor_bottom);
            const Multipole down = Multipole::converged(s, o.tolerance);
            const Multipole up = Multipole::converged(flipped, o.tolerance);
            result.dipoles[i] = std::max({result.dipoles[i], down.dipoles(), up.dipoles()});
            auto spectrum = [&](const Multipole& m, bool reflect) {
                if (!reflect && s.semi_infinite()) return zero;
                return fft.transform(kernel(n, result.cell, reflect ? m.total_reflectance() : m.total_transmittance(),
                                            [&](double r) { return reflect ? m.reflectance(r) : m.transmittance(r); }));
            };
            Spectrum r2 = spectrum(down, true), t2 = spectrum(down, false);
            Spectrum r2b = spectrum(up, true), t2b = spectrum(up, false);
            const double passes = s.semi_infinite() ? 0.0 : std::exp(-s.sigma_t_reduced() * s.thickness);
            const double a_top = s.boundary_factor_top > 0.0 ? s.boundary_factor_top : boundary_factor(s.eta);
            const Boundaries b{fresnel_normal(s.eta), fresnel_normal(s.eta_below), (a_top - 1.0) / (a_top + 1.0)};
            const Spectrum spread = s.semi_infinite() ? zero : diffuse_crossing(fft, n, result.cell, s);
            add_unscattered(passes, b, spread, r2, t2, r2b, t2b);
            unscattered_reduced *= passes * (1.0 - b.bottom_normal);
            unscattered *= s.semi_infinite() ? 0.0 : std::exp(-s.sigma_t() * s.thickness) * (1.0 - b.bottom_normal);
            direct *= s.semi_infinite() ? 0.0 : std::exp(-s.sigma_t() * s.thickness) * (1.0 - b.bottom_normal);
            if (i == 0) {
                R = r2, T = t2, Rb = r2b, Tb = t2b;
                continue;
            }
            Spectrum nR(R.size()), nT(R.size()), nRb(R.size()), nTb(R.size());
            for (size_t k = 0; k < R.size(); ++k) {
                std::complex<float> down_loop(1.0f), up_loop(1.0f);
                if (o.kubelka_munk) {
                    // 1 - R2 R1' can approach 0 at k = 0 for thick, weakly
                    // absorbing layers; |R(k)| <= R(0) < 1 elsewhere. Keep it
                    // away from 0 so no infinity reaches a table.
                    std::complex<float> d1 = 1.0f - r2[k] * Rb[k], d2 = 1.0f - Rb[k] * r2[k];
                    if (std::abs(d1) < 1e-6f) d1 = 1e-6f;
                    if (std::abs(d2) < 1e-6f) d2 = 1e-6f;
                    down_loop = 1.0f / d1;
                    up_loop = 1.0f / d2;
                }
                nR[k] = R[k] + T[k] * r2[k] * Tb[k] * down_loop;
                nT[k] = T[k] * t2[k] * down_loop;
                nRb[k] = r2b[k] + t2b[k] * Rb[k] * t2[k] * up_loop;
                nTb[k] = t2b[k] * Tb[k] * up_loop;
            }
            R.swap(nR), T.swap(nT), Rb.swap(nRb), Tb.swap(nTb);
        }
        // The pure delta (light unscattered through every layer) is not
        // diffuse: take it out of the transmitted spectrum. T counts what is
        // left plus the forward-scattered light that the similarity relation
        // (sigma_t' < sigma_t) had kept in the delta, so that R + T + T_direct
        // + absorption still balance.
        for (auto& v : T) v -= float(unscattered_reduced);
        ChannelResult& ch = result.channel[size_t(c)];
        ch.R = R[0].real();
        ch.T = T[0].real() + (unscattered_reduced - unscattered);
        ch.T_direct = direct;
        // Back to space, then radial averages over annuli one cell wide.
        const auto r_space = fft.back(R), t_space = fft.back(T);
        const int bins = n / 2;
        std::vector<double> rs(size_t(bins), 0.0), ts(size_t(bins), 0.0), counts(size_t(bins), 0.0);
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const double dx = std::min(x, n - x), dy = std::min(y, n - y);
                const int b = int(std::sqrt(dx * dx + dy * dy) + 0.5);
                if (b >= bins) continue;
                rs[size_t(b)] += r_space[size_t(y) * n + x];
                ts[size_t(b)] += t_space[size_t(y) * n + x];
                counts[size_t(b)] += 1.0;
            }
        const double area = result.cell * result.cell;
        ch.R_profile.resize(size_t(bins));
        ch.T_profile.resize(size_t(bins));
        for (int b = 0; b < bins; ++b) {
            ch.R_profile[size_t(b)] = std::max(0.0, rs[size_t(b)] / (counts[size_t(b)] * area));
            ch.T_profile[size_t(b)] = std::max(0.0, ts[size_t(b)] / (counts[size_t(b)] * area));
        }
    }
    for (int b = 0; b < n / 2; ++b) result.radii.push_back(b * result.cell);
    return result;
}

}  // namespace st::optics
