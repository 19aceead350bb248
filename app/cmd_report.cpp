// cmd_report.cpp: `report`, the main job. Scenes (every one by default) on
// both backends, compared and timed; a Markdown summary on stdout, the HTML
// page of report_page.h, and JUnit XML on request.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "app/tool_data.h"
#include "app/progress.h"
#include "app/memory_budget.h"
#include "app/json_text.h"
#include "app/junit.h"
#include "app/backends.h"
#include "app/bench.h"
#include "app/commands.h"
#include "app/comparison.h"
#include "app/provenance.h"
#include "app/report_page.h"
#include "app/report_techniques.h"
#include "app/short_number.h"
#include "image/image_io.h"
#include "scene/scene.h"

namespace st {

namespace {


std::string fixed(double v, int decimals) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(decimals) << v;
    return s.str();
}

std::string cost_markdown(const std::vector<BenchResult>& costs, int frames) {
    std::ostringstream md;
    if (costs.empty()) return "";
    md << "\n## Cost\n\nFrames per second from the median of " << frames
       << " frames per backend, backends interleaved (`shadertwin bench` rules); CPU threads "
       << costs.front().cpu_threads << ", LP_NUM_THREADS " << costs.front().gl_threads
       << ". CPU stage medians in ms.\n\n"
       << "| scene | size | cpu fps | gl fps | cpu / gl | vertex | setup/binning | raster | fragment | blend/output |\n"
       << "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
    for (const auto& r : costs)
        md << "| " << r.scene << " | " << r.width << "x" << r.height << " | " << fixed(r.cpu.fps(), 1) << " | "
           << fixed(r.gl.fps(), 1) << " | " << fixed(r.cpu.fps() / r.gl.fps(), 2) << " | " << short_number(r.cpu_stages.vertex_ms, 3)
           << " | " << short_number(r.cpu_stages.setup_ms, 3) << " | " << short_number(r.cpu_stages.raster_ms, 3) << " | "
           << short_number(r.cpu_stages.fragment_ms, 3) << " | " << short_number(r.cpu_stages.output_ms, 3) << " |\n";
    return md.str();
}

std::string markdown(const std::vector<SceneComparison>& results, const std::string& renderer) {
    std::ostringstream md;
    const auto failed = std::count_if(results.begin(), results.end(), [](auto& c) { return !c.pass(); });
    md << "# shadertwin report\n\n"
       << "shadertwin " << shadertwin_version() << "; reference: " << renderer << "; CPU flags: "
       << cpu_flags() << "\n\n"
       << results.size() - failed << " of " << results.size() << " scenes pass.\n\n"
       << "| scene | result | coverage_mismatch | identical 8-bit | max_diff_8bit | identical float "
          "| max_rel_diff_float | cpu ms | gl ms |\n"
       << "| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
    for (const auto& c : results)
        md << "| " << c.scene << " | " << (c.pass() ? "pass" : "**FAIL**") << " | " << c.coverage_mismatch
           << " | " << short_number(c.metrics.identical_fraction_8bit, 6) << " | " << c.metrics.max_diff_8bit << " | "
           << short_number(c.metrics.identical_fraction_float, 6) << " | " << short_number(c.metrics.max_rel_diff_float, 3)
           << " | " << short_number(c.cpu_ms, 3) << " | " << short_number(c.gl_ms, 3) << " |\n";
    for (const auto& c : results)
        for (const auto& f : c.failures) md << "\n- " << c.scene << ": " << f;
    md << "\n";
    return md.str();
}

}  // namespace

int cmd_report(const std::vector<std::string>& patterns, const std::string& out_dir, int frames,
               const std::string& junit_path, const CommonOptions& common) {
    if (!junit_path.empty()) check_junit_path(junit_path);
    std::vector<Scene> scenes;
    for (const auto& n : patterns.empty() ? builtin_scene_names() : expand_scene_patterns(patterns))
        scenes.push_back(load_scene(n, common.overrides));
    check_memory(scenes, MemoryUse::Compare, common.max_memory);
    std::error_code ec;
    std::filesystem::create_directories(out_dir, ec);
    if (ec) throw std::runtime_error("cannot create folder " + out_dir + ": " + ec.message());

    set_llvmpipe_threads(common.threads);
    Backends backends(common.threads, common.gl_platform, glsl_roots());
    std::vector<SceneComparison> results;
    std::vector<ReportEntry> entries;
    std::vector<BenchResult> costs;
    JunitReport junit("shadertwin report");
    Progress progress("report", scenes.size());
    for (const Scene& s : scenes) {
        progress.step(s.name);
        const auto start = std::chrono::steady_clock::now();
        ReportEntry e{s.name, s.kind, compare_scene(s, backends, out_dir), std::nullopt, s.paper};
        add_junit_cases(junit, s, e.comparison, out_dir,
                        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        if (frames > 0) {
            e.cost = bench_scene(s, backends, frames, 2);
            costs.push_back(*e.cost);
        }
        results.push_back(e.comparison);
        entries.push_back(std::move(e));
    }
    // Failures first, then as given.
    std::stable_sort(results.begin(), results.end(),
                     [](const SceneComparison& a, const SceneComparison& b) { return !a.pass() && b.pass(); });
    std::stable_sort(entries.begin(), entries.end(),
                     [](const ReportEntry& a, const ReportEntry& b) { return !a.comparison.pass() && b.comparison.pass(); });
    const std::string renderer = backends.gl_renderer();
    const std::string cost = cost_markdown(costs, frames);
    const ReportHeader header{tool_name(),
                              "shadertwin " + shadertwin_version() + "; reference: " + renderer + "; Mesa " +
                                  mesa_version(backends.gl_version()) + "; CPU flags: " + cpu_flags() +
                                  (frames > 0 ? "; " + std::to_string(frames) + " timed frames per backend, interleaved"
                                              : std::string()),
                              out_dir, frames};
    std::vector<std::string> techniques;
    for (const ReportEntry& e : entries)
        if (std::find(techniques.begin(), techniques.end(), e.kind) == techniques.end()) techniques.push_back(e.kind);
    const std::vector<SweepChart> charts = copy_sweep_charts(techniques, out_dir);
    write_text_file(out_dir + "/index.html", report_page(header, entries, technique_section(entries, charts)));
    std::cout << markdown(results, renderer) << cost;
    if (!junit_path.empty()) write_junit(junit_path, junit);
    const bool all_pass = std::all_of(results.begin(), results.end(), [](auto& c) { return c.pass(); });
    return all_pass ? 0 : 1;
}

}  // namespace st
