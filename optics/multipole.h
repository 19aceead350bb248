// multipole.h: diffuse reflectance and transmittance of a slab by the dipole
// (Jensen et al. 2001) and the multipole (Donner and Jensen 2005, Eq. 11-16)
// diffusion approximations: radial profiles R(r), T(r) and their totals.
//
// Sign convention (../shared/notes/techniques.md): source positions are signed
// depths below the top surface, z > 0 inside the slab; the virtual source of
// the central dipole sits at z = -(l + 2 z_b) above it. Each pair contributes
// +real - virtual, so the virtual source's negative z adds to R(r), as the
// dipole of Jensen et al. does with a positive z_v. T(r) uses (d - z) both as
// the factor and inside the distance.
#pragma once

#include <vector>

#include "optics/slab.h"

namespace st::optics {

// Where the diffusion source of the incident beam sits.
enum class SourceDepth {
    // The paper: one mean free path l = 1/sigma_t' deep, weight 1. Breaks
    // when l exceeds the thickness (the source lies below the slab; R or T
    // go negative) and counts the unscattered beam into T.
    MeanFreePath,
    // The mean depth of first (reduced) scattering inside the slab,
    // l - d e^(-d/l) / (1 - e^(-d/l)), weighted by the chance of scattering
    // there at all, 1 - e^(-d/l): the same as MeanFreePath for thick slabs,
    // defined for any thickness, and T excludes the unscattered beam.
    FirstScatter,
    // The same for diffuse (cosine-distributed) incidence: the mean depth of
    // first scattering over all directions, weighted by 1 - 2 E3(d / l).
    DiffuseFirstScatter,
};

// 2 E3(tau): the share of diffuse light that crosses a slab of optical
// thickness tau unscattered (by quadrature over the cosine).
double diffuse_unscattered(double tau);

struct SourcePair {
    double z_real, z_virtual;  // signed depths, mm
};

class Multipole {
public:
    // `pairs_per_side` = n of Eq. 11/16: 2n + 1 dipoles (n = 0: the dipole).
    // A semi-infinite slab always has just the one dipole.
    Multipole(const Slab& slab, int pairs_per_side, SourceDepth source = SourceDepth::FirstScatter);

    // The whole image series: totals in closed form, with no truncation
    // error, and profiles from n pairs plus the rest of the series as an
    // integral, n grown until one more pair on each side changes the profiles
    // at r = 0, one period and four periods by less than `tolerance` of their
    // values at r = 0 (with the geometric tail the changes imply), or until
    // `max_pairs_per_side`.
    static Multipole converged(const Slab& slab, double tolerance, SourceDepth source = SourceDepth::FirstScatter,
                               int max_pairs_per_side = 1 << 20);

    double reflectance(double r) const;    // R(r), Eq. 12, per mm^2
    double transmittance(double r) const;  // T(r), Eq. 13, per mm^2
    // Integrals of R and T over the plane, closed form: of the 2n + 1
    // dipoles (the paper's truncation), or of the whole series for converged()
    // and for a non-absorbing slab (whose truncated sums cancel to the first pair).
    double total_reflectance() const;
    double total_transmittance() const;

    int dipoles() const { return int(sources_.size()); }  // 2n + 1
    int pairs_per_side() const { return (dipoles() - 1) / 2; }
    const std::vector<SourcePair>& sources() const { return sources_; }

private:
    SourcePair pair(int i) const;  // the i-th pair of Eq. 16 (0: the central dipole)
    // Profile at r of the sources at i P + c beyond n pairs (|i| > n), for
    // the whole series (converged()); 0 for a truncated one.
    double series_tail(double c, double r, int n) const;

    Slab slab_;
    double alpha_ = 0, sigma_tr_ = 0;  // alpha_ includes the source's weight
    double z_source_ = 0, zb_top_ = 0, zb_bottom_ = 0, period_ = 0;  // mm; z_b = 2 A D
    bool whole_series_ = false;  // totals of the infinite series (converged())
    std::vector<SourcePair> sources_;
};

}  // namespace st::optics
