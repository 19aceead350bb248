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
#include "app/commands/fields.h"
#include "app/error_line.h"
#include "app/output_provenance.h"
#include "app/memory_budget.h"
#include "app/profile_quality.h"
#include "scene/input_error.h"

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
    bench->add_option("scenes", scenes, "built-in scene names or .json paths")->required();
    bench->add_option("--frames", frames, "measured frames per backend (after warm-up)")->check(CLI::Range(1, 100000));
    bench->add_flag("--json", json, "one JSON object per scene and backend");
    bool scaling = false, per_pass = false;
    bench->add_flag("--scaling", scaling,
                    "also run the CPU side on one thread, interleaved, and report the 1 -> N thread scaling");
    bench->add_flag("--passes", per_pass,
                    "also time each pass on both backends (the frame cut after each, interleaved) and list the "
                    "profiles' build times apart");
    add_common(bench, common, gl_given);

    st::SlabOptions slab_options;
    std::vector<CLI::Option*> eta_below_given;  // its default is --eta, so "unset" must not be a value
    auto add_slab_options = [&slab_options, &eta_below_given](CLI::App* cmd) {
        cmd->add_option("--model", slab_options.model, "multipole, dipole or mc")
            ->check(CLI::IsMember({"multipole", "dipole", "mc"}));
        cmd->add_option("--sigma-a", slab_options.sigma_a, "absorption coefficient, 1/mm");
        cmd->add_option("--sigma-s", slab_options.sigma_s, "scattering coefficient, 1/mm");
        cmd->add_option("--g", slab_options.g, "Henyey-Greenstein mean cosine");
        cmd->add_option("--eta", slab_options.eta, "index of the slab relative to the medium above");
        eta_below_given.push_back(
            cmd->add_option("--eta-below", slab_options.eta_below, "relative to the medium below (default: --eta)"));
        cmd->add_option("--thickness", slab_options.thickness, "mm, or inf");
        cmd->add_option("--roughness", slab_options.roughness, "RMS slope of a rough top surface (Beckmann)");
        cmd->add_option("--layers", slab_options.layers_file, "a JSON list of layers, top first (replaces the above)");
        cmd->add_flag("--no-km", slab_options.no_km, "layers: drop the frequency-space correction (first term only)");
        cmd->add_flag("--from-below", slab_options.from_below, "layers: light the stack from below (its last layer first)");
        cmd->add_option("--grid", slab_options.grid, "layers: FFT grid size (power of two)");
        cmd->add_option("--extent", slab_options.extent, "layers: grid width in mm (default: 64 mean free paths)");
        cmd->add_option("--source", slab_options.source,
                        "diffusion source depth: first-scatter (defined for any thickness) or paper (1/sigma_t')")
            ->check(CLI::IsMember({"first-scatter", "paper"}));
        auto* pairs = cmd->add_option("--pairs", slab_options.pairs, "dipole pairs per side (multipole)")
                          ->check(CLI::Range(0, 1000000));  // -1, "from the tolerance", is not a value to give
        cmd->add_option("--tolerance", slab_options.tolerance, "relative tolerance that sets the pairs")->excludes(pairs);
    };
    auto* slab = app.add_subcommand("slab", "total diffuse R and T of a slab (dipole, multipole or Monte Carlo)");
    add_slab_options(slab);
    slab->add_option("--photons", slab_options.photons, "Monte Carlo photons");
    slab->add_option("--seed", slab_options.seed, "Monte Carlo seed");
    slab->add_option("--threads", slab_options.threads, "Monte Carlo threads")->check(CLI::Range(1, 256));
    slab->add_flag("--json", slab_options.json, "one JSON object");
    std::string profile_out;
    double r_max = 10.0;
    int samples = 256;
    auto* profile = app.add_subcommand("profile", "radial R(r) and T(r) tables of a slab (CSV, or EXR)");
    add_slab_options(profile);
    profile->add_option("--out", profile_out, "FILE.csv or FILE.exr")->required();
    profile->add_option("--r-max", r_max, "largest radius, mm");
    profile->add_option("--samples", samples, "number of radii (Monte Carlo: bins)");
    profile->add_option("--photons", slab_options.photons, "Monte Carlo photons per channel");
    profile->add_option("--seed", slab_options.seed, "Monte Carlo seed");
    profile->add_option("--threads", slab_options.threads, "Monte Carlo threads")->check(CLI::Range(1, 256));

    long long figure_photons = 200000;
    int figure_threads = 2;
    auto* figures = app.add_subcommand("optics-figures", "charts and tables of docs/optics.md (Figures 2-3, Table 3 skin, rough surfaces, speed/accuracy)");
    figures->add_option("--out", out_dir, "output folder");
    figures->add_option("--photons", figure_photons, "Monte Carlo photons per run");
    figures->add_option("--threads", figure_threads, "Monte Carlo threads")->check(CLI::Range(1, 256));

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
    sweep->add_option("--frames", sweep_frames, "relief, profile: timed rounds per setting (medians)")->check(CLI::Range(1, 1000));
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
        // A scene's `quality: auto` is resolved by rendering candidates (app/profile_quality.h).
        st::install_quality_resolver(common.threads, common.gl_platform);
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
        if (*fields) return st::cmd_fields(field_kinds);
        if (*bench) return st::cmd_bench(scenes, frames, json, scaling, per_pass, common);
        if (*sweep) {
            if (technique == "relief") return st::cmd_sweep_relief(out_dir, sweep_frames, common);
            if (technique == "profile") return st::cmd_sweep_profile(sweep_scene, out_dir, sweep_frames, common);
            if (technique == "profile-quality")
                return st::cmd_sweep_quality(sweep_scene_option->count() ? std::vector<std::string>{sweep_scene}
                                                                         : std::vector<std::string>{},
                                             out_dir, sweep_frames, common);
            return st::cmd_sweep(technique, out_dir, common);
        }
        std::cerr << "shadertwin: no command given (try --help)\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "shadertwin: " << st::error_line(e.what()) << "\n";
        return 2;
    }
}

}  // namespace st
