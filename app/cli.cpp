// cli.cpp: the command line (see README.md and docs/ for each command).
// Errors of any kind print one line on stderr (plus the GL log after a
// shader compile error) and exit 2.
#include "app/cli.h"

#include <algorithm>
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdlib>
#include <iostream>

#include "app/commands.h"
#include "app/commands/explore.h"
#include "app/commands/new_technique.h"
#include "app/commands/probe.h"
#include "app/commands/sampler_rates.h"
#include "app/commands/fields.h"
#include "app/error_line.h"
#include "app/interface/uniform_interface.h"
#include "app/output_provenance.h"
#include "app/memory_budget.h"
#include "app/option_domain.h"
#include "app/tool_data.h"
#include "app/quality/quality_resolver.h"
#include "scene/input_error.h"
#include "scene/layer_file.h"
#include "scene/scene.h"

namespace {

void add_common(CLI::App* cmd, st::CommonOptions& common, bool& gl_given) {
    cmd->add_option("--set", common.overrides, "override a scene field: PATH=VALUE (repeatable)");
    cmd->add_option("--threads", common.threads, "CPU worker threads")
        ->check(CLI::Range(1, 256))
        ->default_val(2);
    cmd->add_option_function<std::string>(
           "--max-memory",
           [&common](const std::string& size) {
               try {
                   common.max_memory = st::parse_memory_size(size);
               } catch (const std::exception& e) {
                   throw CLI::ValidationError(e.what());
               }
           },
           "refuse a scene whose estimated peak memory exceeds SIZE (4G, 512M); default: what the machine allows")
        ->type_name("SIZE");
    cmd->add_option_function<std::string>(
           "--gl",
           [&common, &gl_given](const std::string& name) {
               try {
                   common.gl_platform = st::parse_gl_platform(name);
                   gl_given = true;
               } catch (const std::exception& e) {
                   throw CLI::ValidationError(e.what());
               }
           },
           "GL reference platform: auto (OSMesa if it loads, else EGL), osmesa or egl; default: "
           "SHADERTWIN_GL, else auto")
        ->type_name("PLATFORM");
}

// The domains of the numeric options of slab, profile and optics-figures
// (issue 26, point 4; app/option_domain.h; docs/optics.md lists them), each
// declared once, here, with why. A value outside its domain is refused by
// the parser, one line, exit 2; a value inside gives a finite answer or a
// one-line refusal of a combination that cannot be computed (an --extent
// too small for the stack, too many dipoles for --samples, a Monte Carlo
// run estimated at hours), never undefined behaviour or NaN.
struct SlabDomains {
    // A layer's coefficients, index and thickness: the bounds a layers file
    // has too (scene/layer_file.h): past them sigma_tr^2 overflows or a
    // boundary becomes a mirror.
    st::OptionDomain coefficient = st::reals_in(0.0, st::kCoefficientMax, "per mm");
    st::OptionDomain eta = st::reals_in(st::kEtaMin, st::kEtaMax);
    st::OptionDomain thickness{
        "[" + st::domain_number(st::kThicknessMin) + ", " + st::domain_number(st::kThicknessMax) + "] mm, or inf",
        [](const std::string& v) {
            if (v == "inf") return true;
            const auto x = st::option_real(v);
            return x && *x >= st::kThicknessMin && *x <= st::kThicknessMax;
        }};
    // Henyey-Greenstein is a distribution for |g| < 1 only (at g = 1 light
    // goes on unscattered). How close to 1 it may come depends on sigma_s:
    // the check that sigma_t' = sigma_a + sigma_s (1 - g) is at least 1e-6
    // per mm (cmd_slab.cpp) decides, with the others.
    st::OptionDomain g{"(-1, 1)", [](const std::string& v) {
                           const auto x = st::option_real(v);
                           return x && *x > -1.0 && *x < 1.0;
                       }};
    // RMS slope of the Beckmann facets: 0 is smooth, 10 a surface of facets
    // near vertical (a layers file's bound too).
    st::OptionDomain roughness = st::reals_in(0.0, 10.0);
    // Truncated sums: 10^4-10^5 pairs settle the slowest (absorption-free)
    // slab; a million is far past that and still a second's work.
    st::OptionDomain pairs = st::integers_in(0, 1000000);
    // Relative changes below 1e-15 are the sums' own rounding (double's
    // epsilon is 2.2e-16): a smaller tolerance only runs the pair search to
    // its cap of 2^20 pairs (10 s for a 256-radius table, hours for a
    // stack's kernels); a tolerance of 1 accepts anything.
    st::OptionDomain tolerance{"[1e-15, 1)", [](const std::string& v) {
                                   const auto x = st::option_real(v);
                                   return x && *x >= 1e-15 && *x < 1.0;
                               }};
    // Monte Carlo photons per run (per channel for a stack): a million is
    // the most the docs use (0.14 s for a 1 mm slab, 10 s for Table 3's skin
    // in three channels on two cores); ten million keeps a run within about
    // two minutes. Deep, nearly lossless media are bounded apart, by the
    // estimated photon steps (cmd_slab.cpp).
    st::OptionDomain photons = st::integers_in(1, 10000000);
    // The seed picks the random streams (a uint64_t): any non-negative long long.
    st::OptionDomain seed = st::integers_in(0, 9223372036854775807LL);
    st::OptionDomain threads = st::integers_in(1, 256);
    // FFT grid cells per side: a power of two (KissFFT's plans, the
    // symmetric kernel); at least 8, so that the kernels' quarter holds two
    // cells; at most 2048: 7.6 s and 250 MB for a three-layer stack here,
    // where 4096 takes four times both (over 30 s, 1 GB).
    st::OptionDomain grid{"a power of two in [8, 2048]", [](const std::string& v) {
                              const auto x = st::option_integer(v);
                              return x && *x >= 8 && *x <= 2048 && (*x & (*x - 1)) == 0;
                          }};
    // Grid width: 0 asks for the default. A stack's kernels reach a quarter
    // of it, which must be at least its most translucent layer's reduced mean
    // free path (optics/layered.cpp refuses less, naming the least): no layer
    // has one shorter than 1 / 3e9 mm, so below 1e-9 mm nothing is taken.
    // At most 1e10 mm, past the largest default (4 x 1024 mean free paths of
    // at most 1e6 mm); at 1e25 the stack's R came out NaN.
    st::OptionDomain extent{"0 (the default) or [1e-9, 1e10] mm", [](const std::string& v) {
                                const auto x = st::option_real(v);
                                return x && (*x == 0.0 || (*x >= 1e-9 && *x <= 1e10));
                            }};
    // The table's largest radius: lengths as a thickness's. A profile's
    // radii square without overflow, and Monte Carlo's bins (r_max /
    // samples, at least 1e-18 mm) are normal numbers whose annuli have an area.
    st::OptionDomain r_max = st::reals_in(st::kThicknessMin, st::kThicknessMax, "mm");
    // Radii of a table (Monte Carlo: bins): a million is 2.5 s for the
    // multipole of 11 dipoles; more dipoles are bounded with the radii
    // together (cmd_profile).
    st::OptionDomain samples = st::integers_in(2, 1000000);
    // optics-figures runs 18 Monte Carlo runs of --photons each, besides
    // about 15 s of fixed work: at least 1000 so that every chart has
    // points; at most a million, about two and a half minutes (the docs'
    // figures use 400,000).
    st::OptionDomain figure_photons = st::integers_in(1000, 1000000);
};

}  // namespace

namespace st {

int run_cli(int argc, char** argv, const std::function<void()>& setup) {
    CLI::App app{"shadertwin: GLSL translucency shaders and their C++ twins, compared on the CPU"};
    app.require_subcommand(0, 1);
    bool version = false;
    app.add_flag("--version", version, "versions of shadertwin, Mesa and LLVM, and CPU flags");

    st::CommonOptions common;
    bool gl_given = false;  // --gl on the command line; else SHADERTWIN_GL decides
    std::vector<std::string> scenes;
    std::string backend = "cpu", out_dir = "out", out_png, action;
    bool json = false;
    std::string diff_a, diff_b;

    app.add_subcommand("list", "built-in scenes, one per line");

    auto* render = app.add_subcommand("render", "render scenes on one backend");
    render->add_option("scenes", scenes, "built-in scene names or .json paths")->required();
    render->add_option("--backend", backend, "cpu or gl")->check(CLI::IsMember({"cpu", "gl"}));
    render->add_option("--out", out_dir, "output folder");
    add_common(render, common, gl_given);

    auto* compare = app.add_subcommand("compare", "render on both backends and compare");
    compare->add_option("scenes", scenes, "built-in scene names or .json paths")->required();
    compare->add_option("--out", out_dir, "output folder");
    compare->add_flag("--json", json, "one JSON object per scene");
    std::string junit;
    compare->add_option("--junit", junit, "also write JUnit XML: a test case per scene and output")->type_name("FILE");
    add_common(compare, common, gl_given);

    auto* diff = app.add_subcommand("diff", "compare two image files");
    diff->add_option("a", diff_a, "first image (taken as the CPU side)")->required();
    diff->add_option("b", diff_b, "second image (the reference)")->required();
    diff->add_option("--out", out_png, "heat map PNG");
    diff->add_flag("--json", json, "JSON output");
    // idiff's thresholds; any of them switches from the strict default
    // criteria to idiff's rule (image/thresholds.h).
    st::Thresholds thresholds;
    std::vector<CLI::Option*> threshold_options = {
        diff->add_option("--fail", thresholds.fail, "a pixel fails when a channel differs by more (default 1e-6)"),
        diff->add_option("--failpercent", thresholds.fail_percent, "percent of pixels that may fail (default 0)"),
        diff->add_option("--hardfail", thresholds.hard_fail, "fail when any channel differs by more (default: none)"),
        diff->add_option("--warn", thresholds.warn, "a pixel warns when a channel differs by more (default 1e-6)"),
        diff->add_option("--warnpercent", thresholds.warn_percent, "percent of pixels that may warn (default 0)"),
        diff->add_option("--hardwarn", thresholds.hard_warn, "warn when any channel differs by more (default: none)")};
    const CLI::Validator non_negative(
        [](std::string& value) {
            char* end = nullptr;
            const double v = std::strtod(value.c_str(), &end);
            const bool number = !value.empty() && end == value.c_str() + value.size();
            return number && std::isfinite(v) && v >= 0 ? std::string() : "'" + value + "' is not a finite number >= 0";
        },
        "", "NON_NEGATIVE");
    for (CLI::Option* o : threshold_options) o->check(non_negative);
    diff->footer(
        "Without threshold options, the images must meet the strict default criteria (every 8-bit pixel equal). With "
        "any of them, idiff's rule: the comparison fails when more than --failpercent of the pixels fail or any "
        "difference exceeds --hardfail, and warns likewise. NaN and infinity differ from everything but "
        "themselves.\nExit codes: 0 the same within bounds (a warning included), 1 the images differ, 2 an error "
        "(an unreadable image, sizes that differ, a bad option).");

    auto* golden = app.add_subcommand("golden", "check or update the committed CPU hashes");
    golden->add_option("action", action, "check or update")->required()->check(CLI::IsMember({"check", "update"}));
    golden->add_option("scenes", scenes, "scenes (default: every built-in scene)");
    golden->add_option("--junit", junit, "also write JUnit XML: a test case per scene and output")->type_name("FILE");
    add_common(golden, common, gl_given);

    int frames = 100;
    auto* bench = app.add_subcommand("bench", "frames per second on both backends, interleaved");
    auto* bench_scenes = bench->add_option("scenes", scenes, "built-in scene names or .json paths");
    bench->add_option("--frames", frames, "measured frames per backend (after warm-up)")->check(CLI::Range(1, 100000));
    bench->add_flag("--json", json, "one JSON object per scene and backend");
    bool scaling = false, per_pass = false;
    bench->add_flag("--scaling", scaling,
                    "also run the CPU side on one thread, interleaved, and report the 1 -> N thread scaling");
    bench->add_flag("--passes", per_pass,
                    "also time each pass on both backends (the frame cut after each, interleaved) and list the "
                    "profiles' build times apart");
    bool samplers = false;
    bench->add_flag("--samplers", samplers,
                    "instead of scenes: samples per second of each sampler entry point, format and min filter "
                    "on both backends (one conformance read a pixel, 512x512)")
        ->excludes(bench_scenes);
    bench->callback([&] {
        if (!samplers && scenes.empty()) throw CLI::ValidationError("bench: name the scenes to measure, or --samplers");
    });
    add_common(bench, common, gl_given);

    st::SlabOptions slab_options;
    const SlabDomains domain;
    std::vector<CLI::Option*> eta_below_given;  // its default is --eta, so "unset" must not be a value
    auto add_slab_options = [&slab_options, &eta_below_given, &domain](CLI::App* cmd) {
        cmd->add_option("--model", slab_options.model, "multipole, dipole or mc")
            ->check(CLI::IsMember({"multipole", "dipole", "mc"}));
        cmd->add_option("--sigma-a", slab_options.sigma_a, "absorption coefficient, 1/mm")->check(domain.coefficient.check());
        cmd->add_option("--sigma-s", slab_options.sigma_s, "scattering coefficient, 1/mm")->check(domain.coefficient.check());
        cmd->add_option("--g", slab_options.g, "Henyey-Greenstein mean cosine")->check(domain.g.check());
        cmd->add_option("--eta", slab_options.eta, "index of the slab relative to the medium above")->check(domain.eta.check());
        eta_below_given.push_back(
            cmd->add_option("--eta-below", slab_options.eta_below, "relative to the medium below (default: --eta)")
                ->check(domain.eta.check()));
        cmd->add_option("--thickness", slab_options.thickness, "mm, or inf")->check(domain.thickness.check());
        cmd->add_option("--roughness", slab_options.roughness, "RMS slope of a rough top surface (Beckmann)")
            ->check(domain.roughness.check());
        cmd->add_option("--layers", slab_options.layers_file, "a JSON list of layers, top first (replaces the above)");
        cmd->add_flag("--no-km", slab_options.no_km, "layers: drop the frequency-space correction (first term only)");
        cmd->add_flag("--from-below", slab_options.from_below, "layers: light the stack from below (its last layer first)");
        cmd->add_option("--grid", slab_options.grid, "layers: FFT grid size (power of two)")->check(domain.grid.check());
        cmd->add_option("--extent", slab_options.extent, "layers: grid width in mm (default: 64 mean free paths)")
            ->check(domain.extent.check());
        cmd->add_option("--source", slab_options.source,
                        "diffusion source depth: first-scatter (defined for any thickness) or paper (1/sigma_t')")
            ->check(CLI::IsMember({"first-scatter", "paper"}));
        auto* pairs = cmd->add_option("--pairs", slab_options.pairs, "dipole pairs per side (multipole)")
                          ->check(domain.pairs.check());  // -1, "from the tolerance", is not a value to give
        cmd->add_option("--tolerance", slab_options.tolerance, "relative tolerance that sets the pairs")
            ->check(domain.tolerance.check())
            ->excludes(pairs);
    };
    auto* slab = app.add_subcommand("slab", "total diffuse R and T of a slab (dipole, multipole or Monte Carlo)");
    add_slab_options(slab);
    slab->add_option("--photons", slab_options.photons, "Monte Carlo photons")->check(domain.photons.check());
    slab->add_option("--seed", slab_options.seed, "Monte Carlo seed")->check(domain.seed.check());
    slab->add_option("--threads", slab_options.threads, "Monte Carlo threads")->check(domain.threads.check());
    slab->add_flag("--json", slab_options.json, "one JSON object");
    std::string profile_out;
    double r_max = 10.0;
    int samples = 256;
    auto* profile = app.add_subcommand("profile", "radial R(r) and T(r) tables of a slab (CSV, or EXR)");
    add_slab_options(profile);
    profile->add_option("--out", profile_out, "FILE.csv or FILE.exr")->required();
    profile->add_option("--r-max", r_max, "largest radius, mm")->check(domain.r_max.check());
    profile->add_option("--samples", samples, "number of radii (Monte Carlo: bins)")->check(domain.samples.check());
    profile->add_option("--photons", slab_options.photons, "Monte Carlo photons per channel")->check(domain.photons.check());
    profile->add_option("--seed", slab_options.seed, "Monte Carlo seed")->check(domain.seed.check());
    profile->add_option("--threads", slab_options.threads, "Monte Carlo threads")->check(domain.threads.check());

    long long figure_photons = 200000;
    int figure_threads = 2;
    auto* figures = app.add_subcommand("optics-figures", "charts and tables of docs/optics.md (Figures 2-3, Table 3 skin, rough surfaces, speed/accuracy)");
    figures->add_option("--out", out_dir, "output folder");
    figures->add_option("--photons", figure_photons, "Monte Carlo photons per run")->check(domain.figure_photons.check());
    figures->add_option("--threads", figure_threads, "Monte Carlo threads")->check(domain.threads.check());

    std::string technique;
    int sweep_frames = 5;
    std::string sweep_scene = "profile-slab-edge";
    auto* sweep = app.add_subcommand("sweep", "a technique's model along sweeps of its inputs (thin-slab: both "
                                              "backends; relief and profile: settings, speed against accuracy, CPU)");
    sweep->add_option("technique", technique, "thin-slab | relief | profile | profile-quality")
        ->required()
        ->check(CLI::IsMember({"thin-slab", "relief", "profile", "profile-quality"}));
    auto* sweep_scene_option = sweep->add_option(
        "--scene", sweep_scene,
        "profile: the flat-slab scene measured against its exact image; profile-quality: the one scene (default: "
        "every built-in profile scene)");
    sweep->add_option("--out", out_dir, "output folder (CSV, SVG charts, Markdown)");
    sweep->add_option("--frames", sweep_frames, "relief, profile, thin-slab: timed rounds per setting (medians)")->check(CLI::Range(1, 1000));
    add_common(sweep, common, gl_given);

    st::ReportOptions report_options;
    auto* report = app.add_subcommand("report", "scenes on both backends, compared and timed, as an HTML page");
    report->add_option("scenes", scenes, "scene names, paths or shell patterns ('relief-*'); default: every scene");
    report->add_option("--out", out_dir, "output folder");
    report->add_option("--junit", junit, "also write JUnit XML: a test case per scene and output")->type_name("FILE");
    report->add_option("--frames", report_options.frames, "frames per backend for the cost table (0: none)")
        ->check(CLI::Range(0, 100000));
    report->add_flag("--exr", report_options.exr,
                     "keep every scene's float images (EXR); by default only failing scenes keep theirs");
    report->add_flag("--brief", report_options.brief,
                     "print a few lines (results per technique, the slowest scene, the report's path) instead of "
                     "the Markdown tables, which DIR/summary.md keeps");
    add_common(report, common, gl_given);

    st::ExploreOptions explore_options;
    auto* explore = app.add_subcommand(
        "explore", "settings nobody chose: fields drawn from each scene kind's declared space, compared on both "
                   "backends; failures shrunk to the fewest fields and written as scene files");
    explore->add_option("targets", explore_options.targets,
                        "scene kinds (relief, thin-slab, ...), scene names or .json paths; default: every kind");
    explore->add_option("--seed", explore_options.seed, "the draws' seed");
    explore->add_option("--cases", explore_options.cases, "at most this many cases")->check(CLI::Range(1L, 100000000L));
    explore->add_option("--time", explore_options.seconds, "start no case after this many seconds (0: no limit)")
        ->check(CLI::Range(0.0, 1e7));
    explore->add_option("--fields", explore_options.max_fields, "fields changed per case: 1 to this")
        ->check(CLI::Range(1, 32));
    explore->add_option("--out", explore_options.out_dir, "output folder: summary.json, reproducers/, failing cases' images");
    explore->add_flag("--json", explore_options.json, "the summary as one JSON object on stdout");
    add_common(explore, common, gl_given);

    std::string probe_scene;
    bool probe_json = false;
    auto* probe = app.add_subcommand(
        "probe", "where a shader and its twin first part: each ST_PROBE(name, value) of the GLSL, in order, written "
                 "out alone on both backends; prints the first probe whose bits differ");
    probe->add_option("scene", probe_scene, "a built-in scene name or .json path")->required();
    probe->add_flag("--json", probe_json, "one JSON object: each probe run, and the first that differs");
    add_common(probe, common, gl_given);

    std::string technique_name, technique_vert, technique_frag, technique_out;
    auto* new_technique = app.add_subcommand(
        "new-technique", "a project for your own shader pair: the twins written up to their bodies (every uniform, "
                         "slot and sampler), a scene kind, one scene and the CMake lines; it builds against this "
                         "install, and compare fails, saying what is left to write, until the bodies are written");
    new_technique->add_option("name", technique_name, "the technique's name, a lower-case C identifier")->required();
    new_technique->add_option("vert", technique_vert, "the vertex shader (GLSL 3.30 or later)")->required();
    new_technique->add_option("frag", technique_frag, "the fragment shader")->required();
    new_technique->add_option("--out", technique_out, "the project folder, new or empty (default: ./NAME)");

    std::vector<std::string> field_kinds;
    auto* fields = app.add_subcommand("fields", "each scene kind's fields, types, domains and defaults (Markdown)");
    fields->add_option("kinds", field_kinds, "scene kinds; default: every kind with a declared space");

    // An empty value is no number (CLI11 would take it as 0): every numeric
    // option of every command checks that its value parses as one.
    const CLI::Validator not_empty(
        [](std::string& value) { return value.empty() ? std::string("an empty value is not a number") : std::string(); },
        "", "NOT_EMPTY");
    for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
        for (CLI::Option* option : sub->get_options()) {
            const std::string type = option->get_type_name();
            if (type.rfind("INT", 0) == 0 || type.rfind("UINT", 0) == 0 || type.rfind("FLOAT", 0) == 0)
                option->check(not_empty);
        }

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "shadertwin: " << st::error_line(e.what()) << "\n";
        return 2;
    }

    try {
        if (setup) setup();
        st::record_build_provenance();
        if (!gl_given) common.gl_platform = st::gl_platform_from_environment();
        // A scene's `quality: auto` is resolved by rendering candidates (app/quality/quality_resolver.h).
        st::install_quality_resolver(common.threads, common.gl_platform);
        // Every scene's draws against what their GLSL declares, before anything renders.
        st::install_frame_check(common.gl_platform);
        if (version) return st::cmd_version(common.gl_platform);
        if (app.got_subcommand("list")) return st::cmd_list();
        if (*render) return st::cmd_render(scenes, backend, out_dir, common);
        if (*compare) return st::cmd_compare(scenes, out_dir, json, junit, common);
        if (*diff) {
            const bool any = std::any_of(threshold_options.begin(), threshold_options.end(),
                                         [](CLI::Option* o) { return o->count() > 0; });
            return st::cmd_diff(diff_a, diff_b, out_png, json,
                                any ? std::optional<st::Thresholds>(thresholds) : std::nullopt);
        }
        if (*golden) return st::cmd_golden(action, scenes, junit, common);
        if (*report) {
            report_options.out_dir = out_dir;
            report_options.junit = junit;
            return st::cmd_report(scenes, report_options, common);
        }
        if (*slab || *profile) {
            for (const CLI::Option* option : (*slab ? slab : profile)->get_options())
                if (option->count() > 0)
                    for (const std::string& name : option->get_lnames()) slab_options.given.insert("--" + name);
            slab_options.eta_below_given =
                std::any_of(eta_below_given.begin(), eta_below_given.end(), [](CLI::Option* o) { return o->count() > 0; });
            if (!slab_options.eta_below_given) slab_options.eta_below = slab_options.eta;
            const int rc = *slab ? st::cmd_slab(slab_options) : st::cmd_profile(slab_options, profile_out, r_max, samples);
            for (const std::string& note : st::take_slab_notes()) std::cerr << "shadertwin: note: " << note << "\n";
            return rc;
        }
        if (*figures) return st::cmd_optics_figures(out_dir, figure_photons, figure_threads);
        if (*explore) return st::cmd_explore(explore_options, common);
        if (*probe) return st::cmd_probe(probe_scene, probe_json, common);
        if (*fields) return st::cmd_fields(field_kinds);
        if (*new_technique) return st::cmd_new_technique(technique_name, technique_vert, technique_frag, technique_out);
        if (*bench && samplers) return st::cmd_bench_samplers(frames, json, common);
        if (*bench) return st::cmd_bench(scenes, frames, json, scaling, per_pass, common);
        if (*sweep) {
            if (technique == "relief") return st::cmd_sweep_relief(out_dir, sweep_frames, common);
            if (technique == "profile") return st::cmd_sweep_profile(sweep_scene, out_dir, sweep_frames, common);
            if (technique == "profile-quality")
                return st::cmd_sweep_quality(sweep_scene_option->count() ? std::vector<std::string>{sweep_scene}
                                                                         : std::vector<std::string>{},
                                             out_dir, sweep_frames, common);
            return st::cmd_sweep(technique, out_dir, sweep_frames, common);
        }
        std::cerr << "shadertwin: no command given (try --help)\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "shadertwin: " << st::error_line(e.what()) << "\n";
        return 2;
    }
}

}  // namespace st
