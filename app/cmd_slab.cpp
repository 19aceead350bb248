// cmd_slab.cpp: `slab`, the diffuse reflectance and transmittance of one
// layer by the dipole or multipole model (optics/), and `profile`, its radial
// R(r) and T(r) tables.
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "image/image_io.h"
#include "optics/monte_carlo.h"
#include "optics/multipole.h"
#include "raster/stage_times.h"
#include "scene/input_error.h"

namespace st {

namespace {

// Normal-incidence Fresnel reflectance of an interface with relative index eta.
double fresnel_normal(double eta) {
    const double r = (eta - 1.0) / (eta + 1.0);
    return r * r;
}

optics::Slab validated(const SlabOptions& o) {
    auto finite_nonneg = [](double v, const char* name) {
        if (!std::isfinite(v) || v < 0.0) throw InputError(std::string(name) + " must be a finite number >= 0");
    };
    finite_nonneg(o.sigma_a, "--sigma-a");
    finite_nonneg(o.sigma_s, "--sigma-s");
    if (!(o.g > -1.0 && o.g < 1.0)) throw InputError("--g must lie in (-1, 1)");
    if (!(o.eta > 0.0) || !std::isfinite(o.eta)) throw InputError("--eta must be a finite number > 0");
    if (!(o.eta_below > 0.0) || !std::isfinite(o.eta_below))
        throw InputError("--eta-below must be a finite number > 0");
    optics::Slab s;
    s.sigma_a = o.sigma_a;
    s.sigma_s = o.sigma_s;
    s.g = o.g;
    s.eta = o.eta;
    s.eta_below = o.eta_below;
    if (o.thickness == "inf") {
        s.thickness = INFINITY;
    } else {
        double d = 0;
        std::istringstream in(o.thickness);
        if (!(in >> d) || !in.eof() || !std::isfinite(d) || d <= 0.0)
            throw InputError("--thickness must be a number > 0 (mm) or 'inf'");
        s.thickness = d;
    }
    if (!(s.sigma_t_reduced() > 0.0)) throw InputError("the medium neither scatters nor absorbs (sigma_t' = 0)");
    if (!(o.tolerance > 0.0 && o.tolerance < 1.0)) throw InputError("--tolerance must lie in (0, 1)");
    if (o.pairs < -1 || o.pairs > 1000000) throw InputError("--pairs must lie in [0, 1000000]");
    // About 1 us per photon per core on this machine for albedos near 0.9;
    // 2e8 photons is several minutes, past that a run is a mistake.
    if (o.photons < 1 || o.photons > 200000000) throw InputError("--photons must lie in [1, 200000000]");
    if (o.seed < 0) throw InputError("--seed must be >= 0");
    return s;
}

optics::Multipole build(const optics::Slab& s, const SlabOptions& o) {
    const auto source = o.source == "paper" ? optics::SourceDepth::MeanFreePath : optics::SourceDepth::FirstScatter;
    if (o.model == "dipole") return optics::Multipole(s, 0, source);
    if (o.pairs >= 0) return optics::Multipole(s, o.pairs, source);
    return optics::Multipole::converged(s, o.tolerance, source);
}

}  // namespace

namespace {

int slab_monte_carlo(const optics::Slab& s, const SlabOptions& o) {
    optics::McSetup setup;
    optics::McLayer layer;
    layer.sigma_a = s.sigma_a;
    layer.sigma_s = s.sigma_s;
    layer.g = s.g;
    layer.n = s.eta;                  // the medium above has index 1
    layer.thickness = s.thickness;
    setup.layers = {layer};
    setup.n_below = s.eta / s.eta_below;
    setup.photons = uint64_t(o.photons);
    setup.seed = uint64_t(o.seed);
    setup.threads = o.threads;
    const auto start = Clock::now();
    setup.progress = [start](double done) {
        if (ms_between(start, Clock::now()) > 2000.0) std::cerr << "mc: " << int(done * 100.0) << " %\n";
    };
    const optics::McResult r = optics::trace_photons(setup);
    nlohmann::json j = {{"model", "mc"},          {"R", r.R},           {"T", r.T},
                        {"T_direct", r.T_direct}, {"R_stderr", r.R_stderr}, {"T_stderr", r.T_stderr},
                        {"specular", r.specular}, {"absorbed", r.absorbed}, {"photons", o.photons},
                        {"seed", o.seed}};
    if (o.json) {
        std::cout << j.dump() << std::endl;
    } else {
        std::cout << std::setprecision(6) << "R " << r.R << " +- " << r.R_stderr << "\nT " << r.T << " +- "
                  << r.T_stderr << "\nT_direct " << r.T_direct << "\nspecular " << r.specular << "\n";
    }
    return 0;
}

}  // namespace

int cmd_slab(const SlabOptions& o) {
    const optics::Slab s = validated(o);
    if (o.model == "mc") return slab_monte_carlo(s, o);
    const optics::Multipole m = build(s, o);
    // Unscattered light at normal incidence: refracted in, attenuated by
    // sigma_t over the thickness, refracted out (interreflections ignored).
    const double t_direct = s.semi_infinite() ? 0.0
                                              : (1.0 - fresnel_normal(s.eta)) * (1.0 - fresnel_normal(s.eta_below)) *
                                                    std::exp(-s.sigma_t() * s.thickness);
    nlohmann::json j = {{"model", o.model},
                        {"R", m.total_reflectance()},
                        {"T", m.total_transmittance()},
                        {"T_direct", t_direct},
                        {"dipole_pairs", m.dipoles()},
                        {"source", o.source},
                        {"sigma_tr", s.sigma_tr()},
                        {"albedo_reduced", s.albedo_reduced()}};
    if (o.model == "multipole" && o.pairs < 0) j["tolerance"] = o.tolerance;
    if (o.json) {
        std::cout << j.dump() << std::endl;
    } else {
        std::cout << std::setprecision(6) << "R " << m.total_reflectance() << "\nT " << m.total_transmittance()
                  << "\nT_direct " << t_direct << "\ndipole_pairs " << m.dipoles() << "\n";
    }
    return 0;
}

int cmd_profile(const SlabOptions& o, const std::string& out, double r_max, int samples) {
    const optics::Slab s = validated(o);
    if (o.model == "mc") throw InputError("profile does not take --model mc yet");
    if (out.empty()) throw InputError("profile needs --out FILE (.csv or .exr)");
    if (!(r_max > 0.0) || !std::isfinite(r_max)) throw InputError("--r-max must be a number > 0 (mm)");
    if (samples < 2 || samples > 1000000) throw InputError("--samples must lie in [2, 1000000]");
    const optics::Multipole m = build(s, o);
    const bool exr = out.size() > 4 && out.compare(out.size() - 4, 4, ".exr") == 0;
    if (exr) {
        // One row, one pixel per radius: channels R(r), T(r), r, 1.
        Image image(samples, 1);
        for (int i = 0; i < samples; ++i) {
            const double r = r_max * i / (samples - 1);
            float* p = image.pixel(i, 0);
            p[0] = float(m.reflectance(r));
            p[1] = float(m.transmittance(r));
            p[2] = float(r);
            p[3] = 1.0f;
        }
        write_exr(out, image, {{"model", o.model}, {"dipole_pairs", std::to_string(m.dipoles())},
                               {"channels", "R(r) per mm^2, T(r) per mm^2, r in mm"}});
    } else {
        std::ostringstream csv;
        csv << std::setprecision(9) << "r_mm,R,T\n";
        for (int i = 0; i < samples; ++i) {
            const double r = r_max * i / (samples - 1);
            csv << r << ',' << m.reflectance(r) << ',' << m.transmittance(r) << '\n';
        }
        write_text_file(out, csv.str());
    }
    std::cerr << "profile: " << samples << " radii to " << r_max << " mm, " << m.dipoles() << " dipoles\n";
    return 0;
}

}  // namespace st
