// cmd_slab.cpp: `slab`, the diffuse reflectance and transmittance of one
// layer by the dipole or multipole model (optics/), and `profile`, its radial
// R(r) and T(r) tables.
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "app/progress.h"
#include "app/json_text.h"
#include "app/profile_table.h"
#include "optics/diffuse_fresnel.h"
#include "optics/layered.h"
#include "optics/monte_carlo.h"
#include "optics/multipole.h"
#include "optics/rough_surface.h"
#include "raster/stage_times.h"
#include "scene/input_error.h"
#include "scene/layer_file.h"

namespace st {

namespace {

// No NaN or infinity reaches a result: inputs are bounded so none should
// arise, and if one does it is a defect to report, not a number to print.
void require_finite(const nlohmann::json& j, const std::string& key = "result") {
    if (j.is_object()) {
        for (const auto& [k, v] : j.items()) require_finite(v, k);
    } else if (j.is_array()) {
        for (const auto& v : j) require_finite(v, key);
    } else if (j.is_number_float() && !std::isfinite(j.get<double>())) {
        throw std::runtime_error(key + " is not finite for these inputs (a defect: please report the command)");
    }
}

std::vector<std::string>& pending_notes() {
    static std::vector<std::string> notes;
    return notes;
}

// The options a single slab and a stack share.
// An option that does nothing for the chosen model is not ignored silently.
// Where the issue's one command line allows it with any model (a script may
// pass --photons to all three), it gets a note, printed once the command has
// succeeded (take_slab_notes): a command that then refuses its input says
// only that; options of stacks given without a stack are refused.
void note_unused(const SlabOptions& o, std::initializer_list<const char*> names, const std::string& why) {
    for (const char* name : names)
        if (o.given.count(name)) pending_notes().push_back(std::string(name) + " " + why + ", ignored");
}

void refuse(const SlabOptions& o, std::initializer_list<const char*> names, const std::string& why) {
    for (const char* name : names)
        if (o.given.count(name)) throw InputError(std::string(name) + " " + why);
}

void check_unused_options(const SlabOptions& o) {
    if (o.layers_file.empty()) refuse(o, {"--no-km", "--grid", "--extent", "--from-below"}, "is for --layers");
    if (o.model != "mc") note_unused(o, {"--photons", "--seed", "--threads"}, "is for --model mc");
    if (o.model == "mc")
        note_unused(o, {"--pairs", "--tolerance", "--source", "--no-km", "--grid", "--extent"},
                    "is for the diffusion models, not --model mc");
    if (o.model == "dipole") note_unused(o, {"--pairs", "--tolerance"}, "is for --model multipole (the dipole is one pair)");
}

// Each option's own domain (--tolerance, --photons, --grid...) is the
// parser's (app/cli.cpp, SlabDomains): the values here lie inside them, and
// what is checked here are the combinations.
void check_shared_options(const SlabOptions& o) { check_unused_options(o); }

// The stack seen from below: the same layers in reverse order, each index
// now relative to the layer that was below it (the air below becomes the
// air above). Reflectance from below differs from above wherever the stack
// is asymmetric.
std::vector<optics::LayerSpec> turned_over(const std::vector<optics::LayerSpec>& layers, const std::string& file) {
    std::vector<double> index{1.0};  // absolute: air, the layers, air
    for (const optics::LayerSpec& l : layers) index.push_back(index.back() * l.eta);
    index.push_back(1.0);
    std::vector<optics::LayerSpec> over;
    for (size_t i = layers.size(); i-- > 0;) {
        optics::LayerSpec l = layers[i];
        if (std::isinf(l.thickness)) throw InputError(file + ": --from-below needs a stack of finite layers");
        if (l.roughness > 0.0)
            throw InputError(file + ": --from-below: roughness is a layer's top surface; a rough bottom is not modelled");
        l.eta = index[i + 1] / index[i + 2];
        over.push_back(l);
    }
    return over;
}

// Reads the layers file and checks the options that go with layers.
std::vector<optics::LayerSpec> read_layers(const SlabOptions& o) {
    for (const char* name : {"--sigma-a", "--sigma-s", "--g", "--eta", "--eta-below", "--thickness", "--roughness",
                             "--pairs", "--source"})
        if (o.given.count(name))
            throw InputError("--layers replaces --sigma-a, --sigma-s, --g, --eta, --eta-below, --thickness, --roughness, "
                             "--pairs and --source: give a layer's values in the file");
    if (o.model == "dipole") throw InputError("--layers takes --model multipole or mc");
    check_shared_options(o);
    std::vector<optics::LayerSpec> layers = read_layer_file(o.layers_file);
    if (o.from_below) layers = turned_over(layers, o.layers_file);
    for (size_t i = 1; i < layers.size(); ++i)
        if (layers[i].roughness > 0.0 && o.model == "mc")
            throw InputError(o.layers_file + ": layer " + std::to_string(i) +
                             ": --model mc has a rough top surface only, not rough inner interfaces");
    return layers;
}

// A photon's mean number of steps in the tracer, roughly (within a few
// times: the Table 3 skin is estimated at 170, and takes about 40). In
// reduced steps (a reduced step is m = 1/(1 - g) steps, after which the
// direction is forgotten; g near 1 is nearly ballistic) a walk ends by
// leaving or by roulette (after about 9.2 / (1 - albedo) steps). To leave,
// it must meet a boundary 1/p times, p = 1 - F_dr the least chance that
// diffuse light crosses a boundary outward (--eta 100: 5e-6), and it meets
// one about sqrt(t) times in its first t steps, so leaving near where it
// came in takes about T_esc = 1/p^2; in a slab of reduced optical depth tau
// it is spread through it after tau^2 steps and leaves by either side at
// 2p/tau a step: T_slab = tau^2 + tau/(2p), infinite for a half-space. The
// time to leave has a t^(-1/2) tail from T_esc to the cut T_cut (roulette or
// T_slab, the smaller): the mean is sqrt(T_esc T_cut), or T_cut when that
// is the smaller. (It was sqrt(min(tau^2, roulette)) alone: --eta 100
// --sigma-a 0.01 --sigma-s 1e9 --thickness 1e6 was put at 1e6 steps a
// photon and one photon ran for minutes; --g 0.9999999999 --sigma-a 2e-6
// --sigma-s 352 --thickness 1e9 at 4e4 where it took 1e9.) Each meeting
// with a boundary is a step of the tracer too: about 1/p of them before a
// photon leaves, and in an optically thin slab 1/tau between interactions
// (--sigma-s 1e-320 --eta 100 --thickness 1e-12: no scattering at all, yet
// 2e5 reflections a photon; behind a rough top each is a walk on the
// microsurface, several times dearer).
double mean_steps(const optics::McSetup& s) {
    double tau = 0.0, tau_actual = 0.0, albedo = 0.0, m = 1.0, p = 1.0;
    double n_above = s.n_above;
    for (const optics::McLayer& l : s.layers) {
        tau += (l.sigma_a + l.sigma_s * (1.0 - l.g)) * l.thickness;  // infinite for a half-space
        tau_actual += (l.sigma_a + l.sigma_s) * l.thickness;
        albedo = std::max(albedo, l.sigma_s / (l.sigma_a + l.sigma_s));
        m = std::max(m, 1.0 / (1.0 - l.g));
        // Both ways across each interface: light is trapped in the denser side.
        p = std::min({p, 1.0 - optics::diffuse_fresnel_reflectance(l.n / n_above),
                      1.0 - optics::diffuse_fresnel_reflectance(n_above / l.n)});
        n_above = l.n;
    }
    p = std::min({p, 1.0 - optics::diffuse_fresnel_reflectance(n_above / s.n_below),
                  1.0 - optics::diffuse_fresnel_reflectance(s.n_below / n_above)});
    p = std::max(p, 1e-12);
    const double roulette = (albedo < 1.0 ? 9.2 / (1.0 - albedo) : INFINITY) / m;
    const double slab = std::isinf(tau) ? INFINITY : tau * tau + tau / (2.0 * p);
    const double cut = std::min(roulette, slab), escape = 1.0 / (p * p);
    const double steps = (escape >= cut ? cut : std::sqrt(escape * cut)) * m;
    const double reflections = std::min(1.0 / p, (steps + 1.0) * (1.0 + 1.0 / tau_actual));
    return steps + reflections;
}

// One channel of a layer stack as the Monte Carlo tracer's setup: absolute
// indices from the relative etas, air above and (for a stack) below.
optics::McSetup mc_setup(const std::vector<optics::LayerSpec>& layers, int channel, const SlabOptions& o,
                         double n_below = 1.0) {
    optics::McSetup setup;
    double n = 1.0;
    for (const optics::LayerSpec& l : layers) {
        n *= l.eta;
        optics::McLayer m;
        m.sigma_a = l.sigma_a[size_t(channel)];
        m.sigma_s = l.sigma_s[size_t(channel)];
        m.g = l.g;
        m.n = n;
        m.thickness = l.thickness;
        setup.layers.push_back(m);
    }
    setup.n_above = 1.0;
    setup.n_below = n_below;
    // A photon in an absorption-free half-space ends only by coming back
    // out, and its time to do so has no finite mean: the run need not end.
    if (std::isinf(setup.layers.back().thickness) && setup.layers.back().sigma_a == 0.0)
        throw InputError("--model mc: an absorption-free semi-infinite layer keeps photons for ever; give it sigma_a > 0 "
                         "or a finite thickness");
    // Nearly so is nearly as bad (mean_steps). About 80 ns per step here.
    const double steps = mean_steps(setup) * double(o.photons);
    if (steps > 1e10) {
        std::ostringstream why;
        why << std::setprecision(2) << "--model mc: about " << steps * 80e-9 / 60.0 / 2.0
            << " minutes on two cores (nearly absorption-free and optically deep, or behind boundaries that reflect "
               "nearly all light back in); use fewer --photons";
        throw InputError(why.str());
    }
    setup.top_roughness = layers.front().roughness;
    setup.photons = uint64_t(o.photons);
    setup.seed = uint64_t(o.seed);
    setup.threads = o.threads;
    // Progress on a terminal (app/progress.h), per channel of a stack.
    const auto progress = std::make_shared<Progress>(
        !o.layers_file.empty() ? "Monte Carlo, channel " + std::to_string(channel) : "Monte Carlo", 0);
    setup.progress = [progress](double done) { progress->note(std::to_string(int(done * 100.0)) + " %"); };
    return setup;
}

optics::LayeredOptions layered_options(const SlabOptions& o) {
    optics::LayeredOptions lo;
    lo.grid = o.grid;
    lo.extent = o.extent;
    lo.kubelka_munk = !o.no_km;
    lo.tolerance = o.tolerance;
    return lo;
}

// The single layer of the options (each inside its domain: app/cli.cpp).
optics::Slab validated(const SlabOptions& o) {
    for (const char* name : {"--sigma-a", "--sigma-s", "--thickness"})
        if (!o.given.count(name))
            throw InputError(std::string("no ") + name + ": give --sigma-a, --sigma-s and --thickness, or --layers FILE");
    optics::Slab s;
    s.sigma_a = o.sigma_a;
    s.sigma_s = o.sigma_s;
    s.g = o.g;
    s.eta = o.eta;
    s.eta_below = o.eta_below;
    s.thickness = o.thickness == "inf" ? INFINITY : std::strtod(o.thickness.c_str(), nullptr);
    if (!(s.sigma_t_reduced() >= kSigmaTReducedMin))
        throw InputError("sigma_a + sigma_s (1 - g) must be at least 1e-6 per mm (the medium barely interacts)");
    if (o.roughness > 0.0 && o.model != "mc") s.boundary_factor_top = optics::rough_boundary_factor(o.roughness, s.eta);
    check_shared_options(o);
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

// The single-layer options as a grey layer of a stack.
optics::LayerSpec grey_layer(const optics::Slab& s, double roughness) {
    optics::LayerSpec layer;
    layer.sigma_a = {s.sigma_a, s.sigma_a, s.sigma_a};
    layer.sigma_s = {s.sigma_s, s.sigma_s, s.sigma_s};
    layer.g = s.g;
    layer.eta = s.eta;
    layer.thickness = s.thickness;
    layer.roughness = roughness;
    return layer;
}

int slab_monte_carlo(const optics::Slab& s, const SlabOptions& o) {
    // One layer may have another medium below.
    optics::McSetup setup = mc_setup({grey_layer(s, o.roughness)}, 0, o, s.eta / s.eta_below);
    const optics::McResult r = optics::trace_photons(setup);
    nlohmann::json j = {{"model", "mc"},          {"R", r.R},           {"T", r.T},
                        {"T_direct", r.T_direct}, {"R_stderr", r.R_stderr}, {"T_stderr", r.T_stderr},
                        {"specular", r.specular}, {"absorbed", r.absorbed}, {"photons", o.photons},
                        {"seed", o.seed}};
    require_finite(j);
    if (o.json) {
        std::cout << json_text(j) << std::endl;
    } else {
        std::cout << std::setprecision(6) << "R " << r.R << " +- " << r.R_stderr << "\nT " << r.T << " +- "
                  << r.T_stderr << "\nT_direct " << r.T_direct << "\nspecular " << r.specular << "\n";
    }
    return 0;
}

}  // namespace

std::vector<std::string> take_slab_notes() { return std::exchange(pending_notes(), {}); }

int cmd_slab(const SlabOptions& o) {
    if (!o.layers_file.empty()) {
        const auto layers = read_layers(o);
        if (o.model == "mc") {
            nlohmann::json j = {{"model", "mc"}, {"layers", layers.size()}, {"photons", o.photons}, {"seed", o.seed}};
            for (const char* key : {"R", "T", "T_direct", "R_stderr", "T_stderr", "specular"}) j[key] = nlohmann::json::array();
            for (int c = 0; c < 3; ++c) {
                const optics::McResult r = optics::trace_photons(mc_setup(layers, c, o));
                j["R"].push_back(r.R);
                j["T"].push_back(r.T);
                j["T_direct"].push_back(r.T_direct);
                j["R_stderr"].push_back(r.R_stderr);
                j["T_stderr"].push_back(r.T_stderr);
                j["specular"].push_back(r.specular);
            }
            require_finite(j);
            if (o.json) {
                std::cout << json_text(j) << std::endl;
            } else {
                std::cout << std::setprecision(6);
                for (const char* key : {"R", "T", "T_direct", "R_stderr", "T_stderr"})
                    std::cout << key << " " << j[key][0] << " " << j[key][1] << " " << j[key][2] << "\n";
            }
            return 0;
        }
        const optics::LayeredResult r = optics::combine_layers(layers, layered_options(o));
        nlohmann::json j = {{"model", "multipole"}, {"layers", layers.size()}, {"km", !o.no_km},
                            {"grid", o.grid}, {"cell_mm", r.cell}, {"dipole_pairs", r.dipoles}};
        if (layers.front().roughness > 0.0) {
            // The rough top's Eq. 24-26 terms, for a renderer (Eq. 25); the
            // same for every channel (one index per layer).
            const double eta = layers.front().eta, m = layers.front().roughness;
            j["roughness"] = m;
            j["rho_d"] = optics::rough_internal_reflectance(m, eta);
            j["A"] = optics::rough_boundary_factor(m, eta);
            j["rho_dt"] = optics::RoughSurface(m, eta).rho_dt_table(16);  // at cos theta = (i + 0.5) / 16
        }
        for (const char* key : {"R", "T", "T_direct", "profile_cut"}) {
            nlohmann::json list = nlohmann::json::array();
            for (const auto& c : r.channel)
                list.push_back(std::string(key) == "R"   ? c.R
                               : std::string(key) == "T" ? c.T
                               : std::string(key) == "T_direct" ? c.T_direct
                                                                 : c.profile_cut);
            j[key] = list;
        }
        require_finite(j);
        if (o.json) {
            std::cout << json_text(j) << std::endl;
        } else {
            std::cout << std::setprecision(6);
            for (const char* key : {"R", "T", "T_direct", "profile_cut"})
                std::cout << key << " " << j[key][0] << " " << j[key][1] << " " << j[key][2] << "\n";
            std::cout << "dipole_pairs";
            for (int d : r.dipoles) std::cout << " " << d;
            std::cout << "\n";
        }
        return 0;
    }
    const optics::Slab s = validated(o);
    if (o.model == "mc") return slab_monte_carlo(s, o);
    const optics::Multipole m = build(s, o);
    // Unscattered light at normal incidence: refracted in, attenuated by
    // sigma_t over the thickness, refracted out (interreflections ignored).
    const double t_direct = s.semi_infinite() ? 0.0
                                              : (1.0 - optics::fresnel_normal(s.eta)) * (1.0 - optics::fresnel_normal(s.eta_below)) *
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
    if (o.roughness > 0.0) {
        // Eq. 24-26: what a renderer applies at entry and exit (Eq. 25).
        const optics::RoughSurface surface(o.roughness, s.eta);
        j["roughness"] = o.roughness;
        j["rho_d"] = optics::rough_internal_reflectance(o.roughness, s.eta);
        j["A"] = s.boundary_factor_top;
        j["rho_dt"] = surface.rho_dt_table(16);  // at cos theta = (i + 0.5) / 16
    }
    require_finite(j);
    if (o.json) {
        std::cout << json_text(j) << std::endl;
    } else {
        std::cout << std::setprecision(6) << "R " << m.total_reflectance() << "\nT " << m.total_transmittance()
                  << "\nT_direct " << t_direct << "\ndipole_pairs " << m.dipoles() << "\n";
        if (o.roughness > 0.0) {
            std::cout << "rho_d " << j["rho_d"].get<double>() << "\nA " << j["A"].get<double>() << "\nrho_dt";
            for (double v : j["rho_dt"]) std::cout << " " << v;
            std::cout << "  (at cos theta = (i + 0.5) / 16)\n";
        }
    }
    return 0;
}

int cmd_profile(const SlabOptions& o, const std::string& out, double r_max, int samples) {
    if (out.empty()) throw InputError("profile needs --out FILE (.csv or .exr)");
    check_profile_path(out);
    ProfileTable table;
    if (o.model == "mc") {
        std::vector<optics::LayerSpec> layers;
        double n_below = 1.0;  // a single slab may have another medium below
        if (!o.layers_file.empty()) {
            layers = read_layers(o);
        } else {
            const optics::Slab s = validated(o);
            layers = {grey_layer(s, o.roughness)};
            n_below = s.eta / s.eta_below;
        }
        const int channels = o.layers_file.empty() ? 1 : 3;
        for (int c = 0; c < channels; ++c) {
            optics::McSetup setup = mc_setup(layers, c, o, n_below);
            setup.bin_width = r_max / samples;
            setup.bins = samples;
            const optics::McResult r = optics::trace_photons(setup);
            table.radii = r.bin_centres;  // the bins' area-weighted centres
            table.R.push_back(r.R_profile);
            table.T.push_back(r.T_profile);
        }
        table.metadata = {{"model", "mc"}, {"photons", std::to_string(o.photons)}, {"seed", std::to_string(o.seed)}};
        write_profile_table(out, table);
        std::cerr << "profile: Monte Carlo, " << o.photons << " photons per channel, bins of " << r_max / samples
                  << " mm\n";
        return 0;
    }
    if (!o.layers_file.empty()) {
        const auto layers = read_layers(o);
        refuse(o, {"--r-max", "--samples"}, "does not apply to a layered table: its radii are the grid's (--grid, --extent)");
        const optics::LayeredResult r = optics::combine_layers(layers, layered_options(o));
        table.radii = r.radii;
        for (const auto& c : r.channel) {
            table.R.push_back(c.R_profile);
            table.T.push_back(c.T_profile);
        }
        table.metadata = {{"model", o.no_km ? "multipole, layered, no KM" : "multipole, layered"},
                          {"grid", std::to_string(o.grid)}};
        write_profile_table(out, table);
        double cut = 0.0;
        for (const auto& c : r.channel) cut = std::max(cut, c.profile_cut);
        std::cerr << "profile: " << r.radii.size() << " radii, cell " << r.cell << " mm, profile_cut " << cut << "\n";
        return 0;
    }
    const optics::Slab s = validated(o);
    const optics::Multipole m = build(s, o);
    // Each radius sums every dipole: about 16 ns a dipole and radius here,
    // so a table of 5e8 of them takes 8 s. --pairs 1000000 (2,000,001
    // dipoles) at the default 256 radii is past that, and so is a converged
    // series of 2^20 pairs at --samples 1000000: hours.
    constexpr double kMaxDipoleRadii = 5e8;
    if (double(m.dipoles()) * samples > kMaxDipoleRadii) {
        std::ostringstream why;
        why << std::setprecision(2) << m.dipoles() << " dipoles at each of " << samples << " radii is about "
            << double(m.dipoles()) * samples * 16e-9 / 60.0 << " minutes, past the bound of 5e8 dipole-radius sums: give fewer --samples"
            << (o.pairs >= 0 ? " or --pairs" : " or a larger --tolerance");
        throw InputError(why.str());
    }
    table.R.resize(1);
    table.T.resize(1);
    for (int i = 0; i < samples; ++i) {
        const double r = r_max * i / (samples - 1);
        table.radii.push_back(r);
        table.R[0].push_back(m.reflectance(r));
        table.T[0].push_back(m.transmittance(r));
    }
    table.metadata = {{"model", o.model}, {"dipole_pairs", std::to_string(m.dipoles())}};
    write_profile_table(out, table);
    std::cerr << "profile: " << samples << " radii to " << r_max << " mm, " << m.dipoles() << " dipoles\n";
    return 0;
}

}  // namespace st
