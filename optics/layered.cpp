// layered.cpp: see layered.h.
//
// Two fluxes. The paper combines one kind of light: every exchange between
// layers diffuse, each layer's response the multipole of a collimated beam.
// Here the incident beam stays collimated until it first scatters, and all
// scattered light is diffuse, so each layer has two responses: to the
// collimated beam from above (the multipole with the first-scattering
// source), and to diffuse light from above and from below (the multipole
// with the diffuse-incidence source, SourceDepth::DiffuseFirstScatter). Per
// frequency, with D and U the diffuse light going down and up between the
// stack so far (s) and the next layer (l), and E the collimated beam that
// crossed the stack unscattered:
//   D = (Tc_s + Rd'_s E Rc_l) / (1 - Rd'_s Rd_l),   U = E Rc_l + Rd_l D,
//   Rc = Rc_s + Td'_s U,   Tc = E Tc_l + Td_l D,
// and the same without the collimated terms for diffuse light from above
// (Rd, Td) and from below (Rd', Td'): for diffuse light this is Eq. 21-22
// with reflectance from below for asymmetric layers; --no-km drops the
// 1 / (1 - Rd'_s Rd_l) loops. Splitting a homogeneous slab into layers then
// gives back nearly its own multipole (docs/optics.md), which the paper's
// single flux did not.
//
// Light that crosses a layer unscattered is carried with the Fresnel
// reflection of its boundaries, to first order (the reflected part crosses
// the layer once more, unscattered or scattered): the collimated beam
// e^(-sigma_t' d) meets the bottom at normal incidence, F(0); diffuse light,
// 2 E3(sigma_t' d) of it, meets a boundary with that boundary's F_dr =
// (A - 1) / (A + 1) (Eq. 7, or Eq. 24 if rough), and spreads sideways as it
// crosses (diffuse_crossing).
#include "optics/layered.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "optics/diffuse_fresnel.h"
#include "optics/fft_grid.h"
#include "optics/multipole.h"
#include "optics/rough_surface.h"

namespace st::optics {

namespace {

using Complex = std::complex<float>;
constexpr double kPi = 3.14159265358979323846;

// Where diffuse light that crosses a layer unscattered comes out, relative to
// where it went in: a Lambertian point source seen through a slab of
// thickness d, d^2 e^(-sigma_t' R) / (pi R^4) with R^2 = r^2 + d^2 (cosine
// out of the source, cosine onto the far plane, 1/R^2, attenuation along the
// slant path), normalised to 1 (its share, 2 E3, is applied separately).
Spectrum diffuse_crossing(const FftGrid& grid, const Slab& s) {
    const double d = s.thickness, sigma = s.sigma_t_reduced();
    return grid.kernel(1.0, [&](double r) {
        const double R = std::sqrt(r * r + d * d);
        return d * d * std::exp(-sigma * (R - d)) / (R * R * R * R);  // e^(-sigma d) and 1/pi go with the scale
    });
}

// A layer's (or a stack's) responses, per frequency: diffuse light out for
// the collimated beam from above (rc up, tc down) and for diffuse light from
// above (rd, td) and from below (rdb back down, tdb up); ec is the share of
// the collimated beam that leaves the bottom unscattered.
struct Responses {
    Spectrum rc, tc, rd, td, rdb, tdb;
    double ec = 0.0;
};

// Each kernel sums its multipole's dipoles at every entry of the grid's
// radial table: about 8 ns a dipole and radius here, so 1e9 of them are
// 8 s, for one layer in one channel. Within that: Table 2's and 3's stacks
// at grid 2048 (1e7). Past it: a layer whose image series needs 10^5 pairs
// and more (a tolerance near 1e-15, or an optically very thin layer) on a
// fine grid, minutes to hours.
constexpr double kMaxDipoleRadii = 1e9;

Responses layer_responses(const FftGrid& grid, const Slab& s, double tolerance, int& dipoles, double& cut,
                          const std::string& which) {
    Slab flipped = s;  // seen from below: the two boundaries swap
    std::swap(flipped.eta, flipped.eta_below);
    std::swap(flipped.boundary_factor_top, flipped.boundary_factor_bottom);
    const Multipole beam = Multipole::converged(s, tolerance);
    const Multipole from_above = Multipole::converged(s, tolerance, SourceDepth::DiffuseFirstScatter);
    const Multipole from_below = Multipole::converged(flipped, tolerance, SourceDepth::DiffuseFirstScatter);
    dipoles = std::max({dipoles, beam.dipoles(), from_above.dipoles(), from_below.dipoles()});
    const double kernels = s.semi_infinite() ? 1.0 : 2.0;  // R, and T of a finite layer
    const double sums = double(beam.dipoles() + from_above.dipoles() + from_below.dipoles()) * kernels *
                        double(grid.kernel_samples());
    if (sums > kMaxDipoleRadii) {
        std::ostringstream m;
        m << std::setprecision(2) << which << ": its image series has "
          << std::max({beam.dipoles(), from_above.dipoles(), from_below.dipoles()}) << " dipoles, "
          << grid.kernel_samples() << " radii each on a grid of " << grid.size() << ": about " << sums * 8e-9 / 60.0
          << " minutes, past the bound of 1e9 dipole-radius sums; give a larger tolerance or a smaller grid";
        throw std::invalid_argument(m.str());
    }
    auto reflected = [&](const Multipole& m) {
        return grid.kernel(m.total_reflectance(), [&](double r) { return m.reflectance(r); }, &cut);
    };
    auto transmitted = [&](const Multipole& m) {
        if (s.semi_infinite()) return grid.zero();
        return grid.kernel(m.total_transmittance(), [&](double r) { return m.transmittance(r); }, &cut);
    };
    Responses l{reflected(beam), transmitted(beam), reflected(from_above), transmitted(from_above),
                reflected(from_below), transmitted(from_below), 0.0};
    if (s.semi_infinite()) return l;

    const double tau = s.sigma_t_reduced() * s.thickness;
    const double ec = std::exp(-tau), ed = diffuse_unscattered(tau);
    const double a_top = s.boundary_factor_top > 0.0 ? s.boundary_factor_top : boundary_factor(s.eta);
    const double a_bottom = s.boundary_factor_bottom > 0.0 ? s.boundary_factor_bottom : boundary_factor(s.eta_below);
    const double f_top = (a_top - 1.0) / (a_top + 1.0), f_bottom = (a_bottom - 1.0) / (a_bottom + 1.0);
    const double f_normal = fresnel_normal(s.eta_below);
    const Spectrum spread = diffuse_crossing(grid, s);
    for (size_t k = 0; k < spread.size(); ++k) {
        const Complex K = spread[k], rd = l.rd[k], td = l.td[k], rdb = l.rdb[k], tdb = l.tdb[k];
        // The beam's F(0) at the bottom comes back up: unscattered, or
        // scattered as diffuse light from below.
        l.rc[k] += float(ec * f_normal * ec * (1.0 - fresnel_normal(s.eta))) + float(ec * f_normal) * tdb;
        l.tc[k] += float(ec * f_normal) * rdb;
        // Diffuse light across, and what the far boundary sends back.
        l.td[k] = td + float(ed * (1.0 - f_bottom)) * K + float(ed * f_bottom) * K * rdb;
        l.rd[k] = rd + float(ed * f_bottom * ed * (1.0 - f_top)) * K * K + float(ed * f_bottom) * K * tdb;
        l.tdb[k] = tdb + float(ed * (1.0 - f_top)) * K + float(ed * f_top) * K * rd;
        l.rdb[k] = rdb + float(ed * f_top * ed * (1.0 - f_bottom)) * K * K + float(ed * f_top) * K * td;
    }
    l.ec = ec * (1.0 - f_normal);
    return l;
}

// The stack `s` with layer `l` put under it (the formulas at the top).
void put_under(Responses& s, const Responses& l, bool kubelka_munk) {
    const auto E = float(s.ec);
    for (size_t k = 0; k < s.rc.size(); ++k) {
        Complex loop(1.0f);
        if (kubelka_munk) {
            // 1 - Rd'_s Rd_l can approach 0 at k = 0 for thick, weakly
            // absorbing layers; |R(k)| <= R(0) < 1 elsewhere. Keep it away
            // from 0 so no infinity reaches a table.
            Complex d = 1.0f - s.rdb[k] * l.rd[k];
            if (std::abs(d) < 1e-6f) d = 1e-6f;
            loop = 1.0f / d;
        }
        const Complex down = (s.tc[k] + s.rdb[k] * E * l.rc[k]) * loop;
        const Complex up = E * l.rc[k] + l.rd[k] * down;
        const Complex diffuse_down = s.td[k] * loop, diffuse_up = l.tdb[k] * loop;
        s.rc[k] = s.rc[k] + s.tdb[k] * up;
        s.tc[k] = E * l.tc[k] + l.td[k] * down;
        s.rd[k] = s.rd[k] + s.tdb[k] * l.rd[k] * diffuse_down;
        s.td[k] = l.td[k] * diffuse_down;
        s.rdb[k] = l.rdb[k] + l.td[k] * s.rdb[k] * diffuse_up;
        s.tdb[k] = s.tdb[k] * diffuse_up;
    }
    s.ec *= l.ec;
}

}  // namespace

namespace {

// How far a layer's profiles reach: diffusion in a slab between extrapolated
// boundaries L apart falls off sideways as e^(-kappa r) with kappa^2 =
// sigma_tr^2 + (pi / L)^2 (the slab's lowest mode); a half-space as
// e^(-sigma_tr r).
double lateral_decay(const Slab& s) {
    const double sigma_tr = s.sigma_tr();
    if (s.semi_infinite()) return sigma_tr;
    const double D = s.diffusion_constant();
    const double a_top = s.boundary_factor_top > 0.0 ? s.boundary_factor_top : boundary_factor(s.eta);
    const double a_bottom = s.boundary_factor_bottom > 0.0 ? s.boundary_factor_bottom : boundary_factor(s.eta_below);
    const double L = s.thickness + 2.0 * a_top * D + 2.0 * a_bottom * D;
    return std::sqrt(sigma_tr * sigma_tr + (kPi / L) * (kPi / L));
}

// The default grid width: the kernels reach a quarter of it, which should
// hold the slowest-falling profile down to e^-8 of its peak's scale, and at
// least 16 reduced mean free paths of the most translucent layer; at most
// 1024 of those (an absorption-free half-space never falls off: its cut-off
// share is reported as profile_cut).
double default_extent(const std::vector<std::array<Slab, 3>>& slabs) {
    double mfp = 1e-3, reach = 0.0;
    for (const auto& layer : slabs)
        for (const Slab& s : layer) {
            mfp = std::max(mfp, s.mean_free_path());
            const double kappa = lateral_decay(s);
            reach = std::max(reach, kappa > 0.0 ? 8.0 / kappa : std::numeric_limits<double>::infinity());
        }
    return 4.0 * std::clamp(reach, 16.0 * mfp, 1024.0 * mfp);
}

}  // namespace

LayeredResult combine_layers(const std::vector<LayerSpec>& layers, const LayeredOptions& o) {
    if (layers.empty()) throw std::invalid_argument("no layers");
    // Absolute indices: air (1) above the first layer and below the last.
    std::vector<double> index{1.0};
    for (const LayerSpec& l : layers) index.push_back(index.back() * l.eta);
    index.push_back(1.0);
    std::vector<std::array<Slab, 3>> slabs(layers.size());
    for (size_t i = 0; i < layers.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const LayerSpec& L = layers[i];
            Slab& s = slabs[i][size_t(c)];
            s.sigma_a = L.sigma_a[size_t(c)];
            s.sigma_s = L.sigma_s[size_t(c)];
            s.g = L.g;
            s.eta = index[i + 1] / index[i];
            s.eta_below = index[i + 1] / index[i + 2];
            s.thickness = L.thickness;
            if (L.roughness > 0.0) s.boundary_factor_top = rough_boundary_factor(L.roughness, s.eta);
        }

    const double extent = o.extent > 0.0 ? o.extent : default_extent(slabs);
    // The kernels reach a quarter of the grid; a layer's profile spreads over
    // at least its reduced mean free path, so a grid whose reach is shorter
    // than the most translucent layer's holds next to nothing of that
    // profile (1e-30 mm gave R = 2e-5 for skin where the default gives 0.44,
    // and a cut share of 1e-59 that said nothing was wrong).
    double mfp = 0.0;
    for (const auto& layer : slabs)
        for (const Slab& s : layer) mfp = std::max(mfp, s.mean_free_path());
    if (!(extent / 4.0 >= mfp) || !std::isfinite(extent)) {
        std::ostringstream m;
        m << "the grid's extent " << extent << " mm is too small: its kernels reach a quarter of it, less than the "
          << "most translucent layer's reduced mean free path (" << mfp << " mm); give at least " << 4.0 * mfp
          << " mm, or 0 for the default";
        throw std::invalid_argument(m.str());
    }
    const FftGrid grid(o.grid, extent / o.grid);
    LayeredResult result;
    result.cell = grid.cell();
    result.dipoles.assign(layers.size(), 0);

    for (int c = 0; c < 3; ++c) {
        ChannelResult& ch = result.channel[size_t(c)];
        Responses stack;
        double direct = 1.0 - fresnel_normal(index[1]);
        double unscattered = 1.0;  // the beam through every layer, e^(-sigma_t d) each: sigma_t, not sigma_t'
        for (size_t i = 0; i < layers.size(); ++i) {
            const Slab& s = slabs[i][size_t(c)];
            const Responses l = layer_responses(grid, s, o.tolerance, result.dipoles[i], ch.profile_cut,
                                                "layer " + std::to_string(i) + ", channel " + std::to_string(c));
            const double passes = s.semi_infinite() ? 0.0 : std::exp(-s.sigma_t() * s.thickness);
            unscattered *= passes * (1.0 - fresnel_normal(s.eta_below));
            direct *= passes * (1.0 - fresnel_normal(s.eta_below));
            if (i == 0) stack = l;
            else put_under(stack, l, o.kubelka_munk);
        }
        // T counts the diffuse light plus what the similarity relation
        // (sigma_t' < sigma_t) kept in the unscattered beam although it
        // scattered forward, so that R + T + T_direct + absorption balance.
        // Single precision: a lossless stack can come to 1 + 1e-7. With g < 0
        // (sigma_t' > sigma_t) the similarity term is negative, and where
        // nearly nothing is transmitted it can outweigh T: T is held at 0.
        ch.R = std::clamp(double(stack.rc[0].real()), 0.0, 1.0);
        ch.T = std::clamp(stack.tc[0].real() + (stack.ec - unscattered), 0.0, 1.0 - ch.R);
        ch.T_direct = direct;
        ch.R_profile = grid.radial_profile(stack.rc);
        ch.T_profile = grid.radial_profile(stack.tc);
    }
    for (int b = 0; b < o.grid / 2; ++b) result.radii.push_back(b * result.cell);
    return result;
}

}  // namespace st::optics
