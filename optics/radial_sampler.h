// radial_sampler.h: a radial diffusion profile R(r) (dipole, multipole,
// layered or Monte Carlo; per mm^2) prepared for the gather pass of
// diffusion-profile rendering (Donner and Jensen 2005, Sec. 3; issue 11):
// how far it reaches, its total, and a fixed disk pattern of samples placed
// by importance (each sample carries an equal share of the total), so that a
// gather sums irradiance samples times one weight instead of looking the
// profile up per sample. Host code; the pattern becomes shader uniforms.
#pragma once

#include <functional>
#include <vector>

namespace st::optics {

struct GatherSample {
    double x = 0, y = 0;  // offset from the shaded point, mm
    double weight = 0;    // its share of the profile's total (mm^0: already times the area it stands for)
};

class RadialSampler {
public:
    // `tail_fraction`: the share of the total the profile may lose beyond
    // r_max. Throws std::invalid_argument for a profile that is negative,
    // not finite, zero everywhere, or still carrying that share at 1e4 mm.
    explicit RadialSampler(std::function<double(double)> profile, double tail_fraction = 1e-4);

    double r_max() const { return r_max_; }
    double total() const { return total_; }  // integral of R(r) 2 pi r dr over [0, r_max]
    // The inverse of the cumulative share C(r) / C(r_max), xi in [0, 1].
    double radius(double xi) const;
    // n samples: radii r_k = radius((k + 1/2) / n), angles k times the golden
    // angle (a Vogel spiral, no two at one angle), weights total / n.
    std::vector<GatherSample> importance_pattern(int n) const;

private:
    std::function<double(double)> profile_;
    double r_max_ = 0, total_ = 0;
    std::vector<double> r_, cumulative_;  // the table radius() inverts
};

// A profile's integral over the plane, as RadialSampler::total(), for a
// profile that may carry nothing at all (a Monte Carlo channel that no
// photon crosses): 0 then, where RadialSampler finds no reach.
double radial_total(const std::function<double(double)>& profile, double tail_fraction);

}  // namespace st::optics
