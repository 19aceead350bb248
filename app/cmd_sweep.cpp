// cmd_sweep.cpp: `sweep thin-slab`. Evaluates the thin-slab model along the
// sweeps of scene/thin_slab_sweep.h on both backends (the thin-slab-sweep
// scene), checks every sample for NaN or infinity and for breaks (relative
// error against a double-precision reference of 1e-3 or more, which a
// discontinuity or a cancellation shows as), compares with the naive float
// formulas, and writes a CSV, SVG charts and the single-scattering accuracy
// table (against the exact slab solution) for docs/thin-slab.md; then the
// variants' speed against accuracy (app/quality/thin_slab_speed.h).
#include <bit>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "app/tool_data.h"
#include "app/memory_budget.h"
#include "app/backends.h"
#include "app/commands.h"
#include "app/quality/thin_slab_speed.h"
#include "app/svg_chart.h"
#include "image/image_io.h"
#include "shading/glsl_math.h"
#include "kernels/thin_slab/thin_slab_model.h"
#include "reference/isotropic_slab.h"
#include "reference/thin_slab_brackets.h"
#include "scene/scene.h"
#include "scene/thin_slab_sweep.h"

namespace st {

namespace {

constexpr double kBreak = 1e-3;  // relative error that counts as a break

// Double-precision references of the four outputs (r, g, b, a) at the
// shader's clamped inputs.
double exact_value(int channel, double tau1, double mu, double mu0) {
    switch (channel) {
        case 0: return reference::frontlit_bracket(tau1, mu, mu0);
        case 1: return reference::backlit_bracket(tau1, mu, mu0);
        case 2: return std::exp(-tau1 / mu);
        default: return -std::expm1(-tau1);
    }
}

// The formulas as printed, in float with llvmpipe's exp: what the stable
// forms replace.
double naive(int channel, float tau1, float mu, float mu0) {
    switch (channel) {
        case 0: return mu0 / (mu + mu0) * (1.0f - glsl::exp(-tau1 * (1.0f / mu + 1.0f / mu0)));
        case 1: return mu0 / (mu - mu0) * (glsl::exp(-tau1 / mu) - glsl::exp(-tau1 / mu0));
        case 2: return glsl::exp(-tau1 / mu);
        default: return 1.0f - glsl::exp(-tau1);
    }
}

double rel_error(double v, double ref) {
    if (!std::isfinite(v)) return INFINITY;
    if (std::abs(ref) < 1e-30) return 0.0;  // underflowed references: no relative meaning
    return std::abs(v - ref) / std::abs(ref);
}

const char* kChannel[4] = {"Eq. 4 bracket", "Eq. 5 bracket", "alpha", "1 - exp(-tau1)"};

std::string fmt(double v) {
    std::ostringstream s;
    s << std::setprecision(3) << v;
    return s.str();
}

}  // namespace

int cmd_sweep(const std::string& technique, const std::string& out_dir, int frames, const CommonOptions& common) {
    if (technique != "thin-slab") throw std::runtime_error("no sweep for '" + technique + "' (known: thin-slab)");
    const Scene scene = load_scene("thin-slab-sweep", common.overrides);
    check_memory({scene}, MemoryUse::Compare, common.max_memory);
    std::error_code ec;
    std::filesystem::create_directories(out_dir, ec);
    if (ec) throw std::runtime_error("cannot create folder " + out_dir + ": " + ec.message());

    Backends backends(common.threads, common.gl_platform, glsl_roots());
    const Image cpu = backends.render(Backend::Cpu, scene.frame).image;
    const Image gl = backends.render(Backend::Gl, scene.frame).image;
    const auto rows = thin_slab_sweep_rows(cpu.width);

    std::ostringstream csv, md;
    csv << "row,axis,x,tau1,mu,mu0,channel,cpu,gl,reference,naive\n";
    csv << std::setprecision(9);
    md << "# Thin-slab sweep\n\n`shadertwin sweep thin-slab`: " << cpu.width << " samples per sweep, both backends. "
       << "Max relative error against a double-precision reference; a break is 1e-3 or more.\n\n"
       << "| sweep | output | non-finite cpu / gl | max rel. error gl | max rel. error cpu | cpu = gl bits | naive float formula |\n"
       << "| --- | --- | --- | --- | --- | --- | --- |\n";
    bool ok = true;
    std::vector<Chart> charts;
    for (size_t r = 0; r < rows.size(); ++r) {
        const SweepRow& row = rows[r];
        const int image_row = cpu.height - 1 - int(r);  // texture row r is window row r
        for (int c = 0; c < 4; ++c) {
            long nonfinite_cpu = 0, nonfinite_gl = 0, same = 0;
            double err_cpu = 0, err_gl = 0, err_naive = 0;
            ChartSeries s_gl{"gl (stable)", "#1f77b4", {}, {}}, s_cpu{"cpu (stable)", "#2ca02c", {}, {}, true},
                s_naive{"naive float", "#d62728", {}, {}};
            for (size_t i = 0; i < row.samples.size(); ++i) {
                const SweepSample& smp = row.samples[i];
                const float mu = std::fmax(smp.mu, MU_MIN), mu0 = std::fmax(smp.mu0, MU_MIN);
                const double ref = exact_value(c, smp.tau1, mu, mu0);
                const float vc = cpu.pixel(int(i), image_row)[c], vg = gl.pixel(int(i), image_row)[c];
                const double vn = naive(c, smp.tau1, mu, mu0);
                nonfinite_cpu += !std::isfinite(vc);
                nonfinite_gl += !std::isfinite(vg);
                same += std::bit_cast<uint32_t>(vc) == std::bit_cast<uint32_t>(vg);
                const double ec_ = rel_error(vc, ref), eg = rel_error(vg, ref), en = rel_error(vn, ref);
                err_cpu = std::max(err_cpu, ec_);
                err_gl = std::max(err_gl, eg);
                err_naive = std::max(err_naive, en);
                const double x = row.axis == "(mu - mu0) / mu0" ? std::abs(smp.x) : smp.x;
                s_gl.x.push_back(x);
                s_gl.y.push_back(std::max(eg, 1e-9));
                s_cpu.x.push_back(x);
                s_cpu.y.push_back(std::max(ec_, 1e-9));
                s_naive.x.push_back(x);
                s_naive.y.push_back(std::max(en, 1e-9));
                csv << '"' << row.name << "\",\"" << row.axis << "\"," << smp.x << ',' << smp.tau1 << ',' << mu << ','
                    << mu0 << ',' << c << ',' << vc << ',' << vg << ',' << ref << ',' << vn << '\n';
            }
            const bool row_ok = nonfinite_cpu == 0 && nonfinite_gl == 0 && err_cpu < kBreak && err_gl < kBreak;
            ok &= row_ok;
            md << "| " << row.name << " | " << kChannel[c] << " | " << nonfinite_cpu << " / " << nonfinite_gl << " | "
               << fmt(err_gl) << " | " << fmt(err_cpu) << " | " << same << " of " << row.samples.size() << " | "
               << (std::isinf(err_naive) ? std::string("non-finite") : fmt(err_naive)) << (row_ok ? "" : " **BREAK**")
               << " |\n";
            // Charts for the places where the printed formulas break down.
            const bool chart = (r == 3 && c == 1) || (r == 0 && c == 3) || (r == 6 && c == 2) || (r == 0 && c == 0);
            if (chart) {
                Chart ch;
                ch.title = std::string(kChannel[c]) + ": " + row.name;
                ch.x_label = row.axis == "(mu - mu0) / mu0" ? "|mu - mu0| / mu0 (both sides of mu0)" : row.axis;
                ch.y_label = "relative error (floored at 1e-9)";
                ch.log_x = ch.log_y = true;
                ch.y_min = 1e-9;
                ch.series = {s_naive, s_gl, s_cpu};
                charts.push_back(ch);
            }
        }
    }

    // Single scattering against the exact slab (normal incidence, mu0 = 1).
    md << "\n## Single scattering against the exact isotropic slab\n\n"
       << "Diffuse reflectance R and transmittance T of an index-matched slab at normal incidence, exact "
          "(all orders, reference/isotropic_slab.cpp) against single scattering (Eq. 4-5 integrated over the "
          "hemisphere). The direct beam e^-tau1 is the same in both.\n\n"
       << "| tau1 | albedo | R exact | R single | R single / exact - 1 | T exact | T single | T single / exact - 1 "
          "| transmitted flux (T+direct) single / exact - 1 | all flux (R+T+direct) single / exact - 1 |\n"
          "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
    for (double albedo : {1.0, 0.5})
        for (double tau1 : {0.01, 0.05, 0.1, 0.2, 0.5, 1.0, 2.0}) {
            const SlabFluxes ex = isotropic_slab_exact(tau1, albedo, 1.0), ss = isotropic_slab_single(tau1, albedo, 1.0);
            const double total_ex = ex.reflectance + ex.transmittance + ex.direct;
            const double total_ss = ss.reflectance + ss.transmittance + ss.direct;
            md << "| " << tau1 << " | " << albedo << " | " << fmt(ex.reflectance) << " | " << fmt(ss.reflectance) << " | "
               << fmt(ss.reflectance / ex.reflectance - 1) << " | " << fmt(ex.transmittance) << " | "
               << fmt(ss.transmittance) << " | " << fmt(ss.transmittance / ex.transmittance - 1) << " | "
               << fmt((ss.transmittance + ss.direct) / (ex.transmittance + ex.direct) - 1) << " | "
               << fmt(total_ss / total_ex - 1) << " |\n";
        }

    md << thin_slab_speed_accuracy(out_dir, frames, common);
    write_text_file(out_dir + "/thin-slab-sweep.csv", csv.str());
    const char* names[] = {"thin-slab-sweep-front.svg", "thin-slab-sweep-one-minus-exp.svg", "thin-slab-sweep-mu-mu0.svg",
                           "thin-slab-sweep-grazing-alpha.svg"};
    for (size_t i = 0; i < charts.size() && i < 4; ++i) write_text_file(out_dir + "/" + names[i], charts[i].svg());
    write_text_file(out_dir + "/thin-slab-sweep.md", md.str());
    std::cout << md.str();
    return ok ? 0 : 1;
}

}  // namespace st
