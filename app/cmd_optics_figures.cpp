// cmd_optics_figures.cpp: `optics-figures`, the charts and tables of
// docs/optics.md: Figure 2 (profiles of slabs 2, 10 and 20 mean free paths
// thick: Monte Carlo, multipole, dipole), Table 3's skin against Monte Carlo,
// and the speed/accuracy trade-offs of the dipole-pair count and the FFT grid,
// with the settings no other setting beats on both axes marked; the rough-
// surface table (Eq. 24 both ways against Monte Carlo); Figure 3
// from the inferred Table 2 materials (materials/table2-*.json).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "app/commands.h"
#include "scene/layer_file.h"
#include "app/progress.h"
#include "app/short_number.h"
#include "app/svg_chart.h"
#include "app/tool_data.h"
#include "image/image_io.h"
#include "optics/layered.h"
#include "optics/microsurface_walk.h"
#include "optics/monte_carlo.h"
#include "optics/diffuse_fresnel.h"
#include "optics/multipole.h"
#include "optics/rough_surface.h"
#include "raster/stage_times.h"

namespace st {

namespace {

using namespace optics;

std::string fmt(double v, int p = 4) {
    std::ostringstream s;
    s << std::setprecision(p) << v;
    return s.str();
}

// Median wall time of `repeats` runs of `work`, in ms.
template <class F>
double time_ms(F&& work, int repeats = 5) {
    std::vector<double> t;
    for (int i = 0; i < repeats; ++i) {
        const auto t0 = Clock::now();
        work();
        t.push_back(ms_between(t0, Clock::now()));
    }
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
}

// Keeps a timed computation's result alive: without it the optimiser (with
// link-time optimisation, across files) drops the work being timed.
void keep(double value) {
    [[maybe_unused]] static volatile double sink;
    sink = value;
}

// Indices of the points no other point beats on both (smaller is better).
std::vector<bool> pareto(const std::vector<double>& cost, const std::vector<double>& error) {
    // Timings within 5 % count as equal (the machine is noisy): j beats i if
    // it is no less accurate, not slower by more than that, and better on
    // one axis by a clear margin.
    constexpr double kSame = 1.05;
    std::vector<bool> best(cost.size(), true);
    for (size_t i = 0; i < cost.size(); ++i)
        for (size_t j = 0; j < cost.size(); ++j)
            if (j != i && error[j] <= error[i] && cost[j] <= cost[i] * kSame &&
                (error[j] < error[i] || cost[j] * kSame < cost[i]))
                best[i] = false;
    return best;
}

// A cost/error scatter with the undominated points drawn again on top.
void write_tradeoff(const std::string& path, const std::string& title, const std::string& x_label,
                    const std::vector<double>& cost, const std::vector<double>& error, const std::vector<bool>& best) {
    Chart ch;
    ch.title = title;
    ch.x_label = x_label;
    ch.y_label = "max relative error";
    ch.log_x = ch.log_y = true;
    ChartSeries all{"all settings", "#1f77b4", cost, error}, front{"undominated", "#d62728", {}, {}};
    for (size_t i = 0; i < cost.size(); ++i)
        if (best[i]) front.x.push_back(cost[i]), front.y.push_back(error[i]);
    ch.series = {all, front};
    write_text_file(path, ch.svg(720, 420));
}

Slab notes_slab(double d) {
    Slab s;
    s.sigma_a = 0.00127;
    s.sigma_s = 0.99873;
    s.thickness = d;
    return s;
}

}  // namespace

int cmd_optics_figures(const std::string& out_dir, long long photons, int threads) {
    // --photons and --threads lie in their domains (app/cli.cpp, SlabDomains).
    std::error_code ec;
    std::filesystem::create_directories(out_dir, ec);
    if (ec) throw std::runtime_error("cannot create folder " + out_dir + ": " + ec.message());
    std::ostringstream md;
    md << "# Optics figures\n\n`shadertwin optics-figures --photons " << photons << "`\n\n";
    Progress progress("optics-figures", 0);

    // Figure 2: radial profiles at 2, 10, 20 mean free paths.
    for (double d : {2.0, 10.0, 20.0}) {
        progress.step("Figure 2, " + short_number(d) + " mfp");
        McSetup setup;
        McLayer l;
        l.sigma_a = 0.00127;
        l.sigma_s = 0.99873;
        l.thickness = d;
        setup.layers = {l};
        setup.photons = uint64_t(photons);
        setup.threads = threads;
        setup.bin_width = 0.1;
        setup.bins = 100;
        const McResult mc = trace_photons(setup);
        const Multipole multi = Multipole::converged(notes_slab(d), 1e-6);
        const Multipole paper = Multipole::converged(notes_slab(d), 1e-6, SourceDepth::MeanFreePath);
        const Multipole dipole(notes_slab(d), 0, SourceDepth::MeanFreePath);
        Chart ch;
        ch.title = "Figure 2: slab " + fmt(d, 3) + " mean free paths thick (1 mm mfp, albedo' 0.99873)";
        ch.x_label = "r (mm)";
        ch.y_label = "R(r), T(r) per mm^2";
        ch.log_y = true;
        ch.x_min = 0.0;
        ChartSeries r_mc{"R Monte Carlo", "#000000", {}, {}}, t_mc{"T Monte Carlo", "#777777", {}, {}};
        ChartSeries r_mp{"R multipole", "#1f77b4", {}, {}}, t_mp{"T multipole", "#1f77b4", {}, {}, true};
        ChartSeries r_pp{"R multipole, paper source", "#2ca02c", {}, {}}, r_dp{"R dipole", "#d62728", {}, {}};
        for (int b = 0; b < setup.bins; ++b) {
            const double r = mc.bin_centres[size_t(b)];
            r_mc.x.push_back(r), r_mc.y.push_back(mc.R_profile[size_t(b)]);
            t_mc.x.push_back(r), t_mc.y.push_back(mc.T_profile[size_t(b)]);
            r_mp.x.push_back(r), r_mp.y.push_back(multi.reflectance(r));
            t_mp.x.push_back(r), t_mp.y.push_back(multi.transmittance(r));
            r_pp.x.push_back(r), r_pp.y.push_back(paper.reflectance(r));
            r_dp.x.push_back(r), r_dp.y.push_back(dipole.reflectance(r));
        }
        ch.series = {r_mc, t_mc, r_mp, t_mp, r_pp, r_dp};
        write_text_file(out_dir + "/figure2-" + fmt(d, 3) + "mfp.svg", ch.svg(720, 420));
    }

    // Figure 3: the inferred two-layer materials of Table 2, KM and no-KM
    // against Monte Carlo (one channel: the materials are grey).
    for (const char* name : {"left", "middle", "right"}) {
        progress.step(std::string("Figure 3, ") + name);
        const auto layers = read_layer_file(materials_dir() + "/table2-" + name + ".json");
        LayeredOptions lo;
        lo.grid = 512;
        lo.extent = 64.0;
        const LayeredResult km = combine_layers(layers, lo);
        lo.kubelka_munk = false;
        const LayeredResult plain = combine_layers(layers, lo);
        McSetup setup;
        double n = 1.0;
        for (const LayerSpec& l : layers) {
            n *= l.eta;
            setup.layers.push_back({l.sigma_a[0], l.sigma_s[0], l.g, n, l.thickness});
        }
        setup.photons = uint64_t(photons);
        setup.threads = threads;
        setup.bin_width = 0.1;
        setup.bins = 100;
        const McResult mc = trace_photons(setup);
        Chart ch;
        ch.title = std::string("Figure 3 (") + name + "): inferred Table 2 material, reflectance and transmittance";
        ch.x_label = "r (mm)";
        ch.y_label = "R(r), T(r) per mm^2";
        ch.log_y = true;
        ch.x_min = 0.0;
        ch.x_max = 10.0;
        ch.series = {{"R Monte Carlo", "#000000", mc.bin_centres, mc.R_profile},
                     {"R KM", "#1f77b4", km.radii, km.channel[0].R_profile},
                     {"R no KM", "#d62728", plain.radii, plain.channel[0].R_profile}};
        if (std::isfinite(layers.back().thickness)) {
            ch.series.push_back({"T Monte Carlo", "#777777", mc.bin_centres, mc.T_profile, true});
            ch.series.push_back({"T KM", "#1f77b4", km.radii, km.channel[0].T_profile, true});
            ch.series.push_back({"T no KM", "#d62728", plain.radii, plain.channel[0].T_profile, true});
        }
        write_text_file(out_dir + "/figure3-" + name + ".svg", ch.svg(720, 420));
    }

    // Table 3's skin: layered multipole against Monte Carlo, per channel.
    {
        progress.step("skin");
        const std::vector<LayerSpec> skin = {
            {{2.1, 2.1, 5.0}, {48.0, 60.0, 65.0}, 0.0, 1.4, 0.03, 0.0},
            {{0.16, 0.19, 0.30}, {32.0, 40.0, 46.0}, 0.25, 1.34 / 1.4, 0.05, 0.0},
            {{0.085, 1.0, 25.0}, {4.5, 4.7, 4.8}, 0.8, 1.4 / 1.34, INFINITY, 0.0}};
        LayeredOptions lo;
        lo.grid = 512;
        lo.extent = 20.0;
        const LayeredResult km = combine_layers(skin, lo);
        Chart ch;
        ch.title = "Table 3 skin: reflectance profile, KM-layered multipole (solid) and Monte Carlo (dashed)";
        ch.x_label = "r (mm)";
        ch.y_label = "R(r) per mm^2";
        ch.log_y = true;
        ch.x_max = 5.0;
        const char* colours[3] = {"#d62728", "#2ca02c", "#1f77b4"};
        const char* names[3] = {"red", "green", "blue"};
        md << "## Table 3 skin, total diffuse reflectance\n\n| channel | KM layered multipole | Monte Carlo |\n| --- | --- | --- |\n";
        for (int c = 0; c < 3; ++c) {
            McSetup setup;
            double n = 1.0;
            for (const LayerSpec& s : skin) {
                n *= s.eta;
                setup.layers.push_back({s.sigma_a[size_t(c)], s.sigma_s[size_t(c)], s.g, n, s.thickness});
            }
            setup.photons = uint64_t(photons);
            setup.threads = threads;
            setup.bin_width = 0.05;
            setup.bins = 100;
            const McResult mc = trace_photons(setup);
            ChartSeries k{std::string("KM ") + names[c], colours[c], km.radii, km.channel[size_t(c)].R_profile};
            ChartSeries m{std::string("MC ") + names[c], colours[c], mc.bin_centres, mc.R_profile, true};
            ch.series.push_back(k);
            ch.series.push_back(m);
            md << "| " << names[c] << " | " << fmt(km.channel[size_t(c)].R) << " | " << fmt(mc.R) << " +- "
               << fmt(mc.R_stderr, 2) << " |\n";
        }
        write_text_file(out_dir + "/skin-table3.svg", ch.svg(720, 420));
    }

    // Rough top surfaces (Eq. 23-26): the diffusion model with rho_d read
    // from inside and by reciprocity, against the tracer's facet-sampled
    // surface, on a semi-infinite medium whose diffusion error is moderate.
    {
        progress.step("rough surfaces");
        Slab s;
        s.sigma_a = 1.0;
        s.sigma_s = 9.0;
        s.eta = 1.5;
        md << "\n## Rough top surfaces (semi-infinite, sigma_a 1, sigma_s 9 /mm, g 0, eta 1.5, normal incidence)\n\n"
           << "Diffusion columns: rho_dt(1) x multipole R with A from rho_d (Eq. 24). Monte Carlo: diffuse R per incident "
              "photon with the energy-conserving walk on the microsurface (the truth), and with single bounces, which lose "
              "the share in the last column.\n\n"
           << "| m | rho_d of the walk | rho_d reciprocal | R diffusion, reciprocal | rho_d inside | R diffusion, inside | "
              "Monte Carlo R, walk | Monte Carlo R, single bounce | lost by single bounces |\n"
              "| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
        for (double m : {0.0, 0.1, 0.5, 1.0}) {
            const RoughSurface surface(m, s.eta);
            auto diffusion = [&](InternalReflection how, double& rho_d) {
                Slab r = s;
                rho_d = m > 0.0 ? rough_internal_reflectance(m, s.eta, how) : diffuse_fresnel_reflectance(s.eta);
                if (m > 0.0) r.boundary_factor_top = rough_boundary_factor(m, s.eta, how);
                return surface.rho_dt(1.0) * Multipole(r, 0).total_reflectance();
            };
            double rd_rec = 0.0, rd_in = 0.0;
            const double r_rec = diffusion(InternalReflection::Reciprocal, rd_rec);
            const double r_in = diffusion(InternalReflection::Inside, rd_in);
            McSetup setup;
            setup.layers = {{s.sigma_a, s.sigma_s, 0.0, s.eta, INFINITY}};
            setup.top_roughness = m;
            setup.photons = uint64_t(photons);
            setup.threads = threads;
            const McResult walk = trace_photons(setup);
            setup.top_multiple_scattering = false;
            const McResult single = trace_photons(setup);
            const double lost = 1.0 - single.specular - single.R - single.T - single.T_direct - single.absorbed;
            const std::string rd_walk = m > 0.0 ? fmt(walk_internal_reflectance(m, s.eta, uint64_t(photons) * 2)) : "-";
            md << "| " << (m > 0.0 ? fmt(m) : std::string("smooth")) << " | " << rd_walk << " | " << fmt(rd_rec) << " | " << fmt(r_rec)
               << " | " << fmt(rd_in) << " | " << fmt(r_in) << " | " << fmt(walk.R) << " +- " << fmt(walk.R_stderr, 2)
               << " | " << fmt(single.R) << " +- " << fmt(single.R_stderr, 2) << " | " << fmt(lost, 3) << " |\n";
        }
    }

    // Dipole pairs against error and build time: the notes' 2 mm slab (slow
    // convergence); error against 2000 pairs per side, over totals and the
    // profile at 64 radii to 8 mm; time to build and tabulate.
    {
        progress.step("pairs");
        const Slab s = notes_slab(2.0);
        const Multipole ref(s, 2000);
        std::vector<double> radii;
        for (int i = 0; i < 64; ++i) radii.push_back(8.0 * i / 63.0);
        md << "\n## Dipole pairs: accuracy against cost (2 mm slab, 1 mm mfp, albedo' 0.99873)\n\n"
           << "| pairs per side | dipoles | max rel. error R, T totals | max rel. error of the profiles | ... relative to r = 0 | build + 64-radius table, ms | best |\n"
           << "| --- | --- | --- | --- | --- | --- | --- |\n";
        // Truncated sums (the paper's), then the whole series of converged()
        // at three tolerances (its pair search counted in the time).
        struct Setting {
            std::string label;
            int pairs;
            double tolerance;  // 0: a truncated sum of `pairs`
        };
        std::vector<Setting> settings;
        for (int n : {0, 1, 2, 3, 5, 8, 12, 16, 20, 25, 30, 35, 40, 60, 100, 200, 500, 1000})
            settings.push_back({std::to_string(n), n, 0.0});
        for (double tol : {1e-3, 1e-6, 1e-9}) {
            const int n = Multipole::converged(s, tol).pairs_per_side();
            std::ostringstream label;
            label << n << " + series tail (tolerance " << tol << ")";
            settings.push_back({label.str(), n, tol});
        }
        auto build = [&](const Setting& set) { return set.tolerance > 0.0 ? Multipole::converged(s, set.tolerance) : Multipole(s, set.pairs); };
        std::vector<double> cost, err_total, err_profile, err_peak;
        for (const Setting& set : settings) {
            const Multipole m = build(set);
            const double et = std::max(std::abs(m.total_reflectance() / ref.total_reflectance() - 1.0),
                                       std::abs(m.total_transmittance() / ref.total_transmittance() - 1.0));
            double ep = 0.0, e0 = 0.0;
            for (double r : radii) {
                ep = std::max(ep, std::abs(m.reflectance(r) / ref.reflectance(r) - 1.0));
                ep = std::max(ep, std::abs(m.transmittance(r) / ref.transmittance(r) - 1.0));
                e0 = std::max(e0, std::abs(m.reflectance(r) - ref.reflectance(r)) / ref.reflectance(0.0));
                e0 = std::max(e0, std::abs(m.transmittance(r) - ref.transmittance(r)) / ref.transmittance(0.0));
            }
            err_peak.push_back(std::max(e0, 1e-16));
            double sink = 0.0;
            const double ms = time_ms([&] {
                const Multipole built = build(set);
                for (double r : radii) sink += built.reflectance(r) + built.transmittance(r);
            });
            keep(sink);
            cost.push_back(ms);
            err_total.push_back(std::max(et, 1e-16));
            err_profile.push_back(std::max(ep, 1e-16));
        }
        std::vector<double> worst(settings.size());
        for (size_t i = 0; i < settings.size(); ++i) worst[i] = std::max(err_total[i], err_profile[i]);
        const auto best = pareto(cost, worst);
        for (size_t i = 0; i < settings.size(); ++i)
            md << "| " << settings[i].label << " | " << 2 * settings[i].pairs + 1 << " | " << fmt(err_total[i], 3) << " | "
               << fmt(err_profile[i], 3) << " | " << fmt(err_peak[i], 3) << " | " << fmt(cost[i], 3) << " | "
               << (best[i] ? "**yes**" : "") << " |\n";
        write_tradeoff(out_dir + "/pairs-speed-accuracy.svg",
                       "Dipole pairs: error against build time (red: no other setting beats it on both)",
                       "build + table time (ms)", cost, worst, best);
    }

    // FFT grid and extent against error and time: two 1 mm halves of a 2 mm
    // slab (the Monte Carlo of the whole is the truth for the totals), and
    // the finest setting for the profile.
    {
        progress.step("grid");
        LayerSpec half;
        half.sigma_a = {0.01, 0.01, 0.01};
        half.sigma_s = {1.0, 1.0, 1.0};
        half.thickness = 1.0;
        const std::vector<LayerSpec> halves{half, half};
        McSetup setup;
        McLayer l;
        l.sigma_a = 0.01;
        l.sigma_s = 1.0;
        l.thickness = 2.0;
        setup.layers = {l};
        setup.photons = uint64_t(photons);
        setup.threads = threads;
        setup.bin_width = 0.25;  // wide enough that 4 mm out a bin holds ~1,000 photons of 400,000
        setup.bins = 40;
        const McResult truth = trace_photons(setup);
        LayeredOptions fine;
        fine.grid = 1024;
        fine.extent = 128.0;
        const LayeredResult reference = combine_layers(halves, fine);
        md << "\n## FFT grid and extent: accuracy against cost (two 1 mm halves of a 2 mm slab)\n\n"
           << "Totals against the Monte Carlo of the whole slab (R " << fmt(truth.R) << " +- " << fmt(truth.R_stderr, 2)
           << ", T " << fmt(truth.T) << " +- " << fmt(truth.T_stderr, 2)
           << "); profile against Monte Carlo at radii 0.5 to 4 mm (the model's error and the grid's; further out the "
              "Monte Carlo's own noise passes 5 %), and against grid 1024 over 128 mm at 0.5 to 8 mm (the grid's own "
              "error; 512 over 64 mm has the same cells, so its error there is small by construction). The chart and "
              "the best column use the larger of the errors against Monte Carlo.\n\n"
           << "| grid | extent (mm) | cell (mm) | error R, T vs MC | max rel. error of R(r) vs grid 1024 | ... vs MC | ms | best |\n"
           << "| --- | --- | --- | --- | --- | --- | --- | --- |\n";
        struct Setting { int grid; double extent; };
        std::vector<Setting> settings;
        for (int g : {32, 64, 128, 256, 512})
            for (double e : {16.0, 32.0, 64.0, 128.0}) settings.push_back({g, e});
        std::vector<double> cost, error;
        std::vector<std::string> rows;
        for (const Setting& st : settings) {
            LayeredOptions o;
            o.grid = st.grid;
            o.extent = st.extent;
            LayeredResult r;
            const double ms = time_ms([&] { r = combine_layers(halves, o); }, 3);
            const double et = std::max(std::abs(r.channel[0].R - truth.R), std::abs(r.channel[0].T - truth.T));
            double ep = 0.0, ep_mc = 0.0;
            for (double radius = 0.5; radius <= 8.0; radius += 0.5) {
                // Linear in r between annulus centres, so grids of different
                // cells compare at the same radius.
                auto at = [radius](const LayeredResult& x) {
                    const double f = radius / x.cell;
                    const size_t b = std::min(x.radii.size() - 2, size_t(f));
                    const double t = std::min(1.0, f - double(b));
                    return x.channel[0].R_profile[b] * (1.0 - t) + x.channel[0].R_profile[b + 1] * t;
                };
                ep = std::max(ep, std::abs(at(r) / at(reference) - 1.0));
                if (radius > 4.0) continue;
                // Monte Carlo bins 0.25 mm wide, linear between their centres.
                const auto& rc = truth.bin_centres;
                const size_t b = size_t(std::upper_bound(rc.begin(), rc.end(), radius) - rc.begin()) - 1;
                const double t = (radius - rc[b]) / (rc[b + 1] - rc[b]);
                const double mc = truth.R_profile[b] * (1.0 - t) + truth.R_profile[b + 1] * t;
                ep_mc = std::max(ep_mc, std::abs(at(r) / mc - 1.0));
            }
            cost.push_back(ms);
            error.push_back(std::max(et, ep_mc));
            std::ostringstream row;
            row << "| " << st.grid << " | " << st.extent << " | " << fmt(st.extent / st.grid, 3) << " | " << fmt(et, 3)
                << " | " << fmt(ep, 3) << " | " << fmt(ep_mc, 3) << " | " << fmt(ms, 3) << " | ";
            rows.push_back(row.str());
        }
        const auto best = pareto(cost, error);
        for (size_t i = 0; i < settings.size(); ++i) md << rows[i] << (best[i] ? "**yes**" : "") << " |\n";
        write_tradeoff(out_dir + "/grid-speed-accuracy.svg",
                       "FFT grid x extent: error against time (red: undominated)",
                       "time for the two-layer combination (ms)", cost, error, best);
    }
    write_text_file(out_dir + "/optics-figures.md", md.str());
    std::cout << md.str();
    return 0;
}

}  // namespace st
